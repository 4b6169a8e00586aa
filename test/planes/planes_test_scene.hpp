#pragma once
// Test scenes for the plane and blob stages: a camera looking down at a table at 40 degrees,
// boxes placed on it, and "perfect" surface patches taken from the renderer's face ids (so these
// tests do not depend on the normal, edge and region-growing stages).

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>

#include "blobs/grow_blobs.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "planes/support_planes.hpp"
#include "synthetic_scene.hpp"
#include "tabletop_frame.hpp"

namespace facet::test {

using Overrides = std::map<std::string, ParamValue>;

inline PointImage scene_points(const RenderedScene& scene, double max_depth_m = 4.0) {
  PointImage out;
  out.camera = scene.camera;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  out.points = cv::Mat(scene.depth_m.size(), CV_32FC3, cv::Scalar::all(nan));
  for (int v = 0; v < scene.depth_m.rows; ++v) {
    for (int u = 0; u < scene.depth_m.cols; ++u) {
      const double z = scene.depth_m.at<float>(v, u);
      if (!(z > 0.0) || z > max_depth_m) continue;
      out.points.at<cv::Vec3f>(v, u) = cv::Vec3f(
          static_cast<float>((u - scene.camera.cx) * z / scene.camera.fx),
          static_cast<float>((v - scene.camera.cy) * z / scene.camera.fy), static_cast<float>(z));
    }
  }
  return out;
}

// One patch per rendered face with a valid point, ids 1..count in raster order.
inline LabelImage face_patches(const RenderedScene& scene, const PointImage& points) {
  LabelImage out;
  out.camera = scene.camera;
  out.labels = cv::Mat::zeros(scene.face.size(), CV_32SC1);
  std::map<int, int> id_of_face;
  for (int v = 0; v < scene.face.rows; ++v) {
    for (int u = 0; u < scene.face.cols; ++u) {
      const int face = scene.face.at<int>(v, u);
      if (face == 0 || !std::isfinite(points.points.at<cv::Vec3f>(v, u)[2])) continue;
      auto [it, added] = id_of_face.try_emplace(face, static_cast<int>(id_of_face.size()) + 1);
      out.labels.at<int>(v, u) = it->second;
    }
  }
  out.count = static_cast<std::int32_t>(id_of_face.size());
  return out;
}

struct PlanesResult {
  SupportPlanes planes;
  LabelImage plane_labels;
  LabelImage patches;
  std::vector<std::string> warnings;
  PatchAdjacency adjacency;
};

inline PlanesResult run_planes(const LabelImage& patches, const PointImage& points,
                               const Overrides& params = {}) {
  testing::StageRunner<planes::SupportPlaneStage> runner(params);
  runner.set_input("patches", Packet::make(patches));
  runner.set_input("points", Packet::make(points));
  runner.run();
  return {runner.output<SupportPlanes>("planes"), runner.output<LabelImage>("plane_labels"),
          runner.output<LabelImage>("patches"), runner.warnings(),
          runner.output<PatchAdjacency>("adjacency")};
}

inline LabelImage run_blobs(const LabelImage& patches, const PointImage& points,
                            const SupportPlanes* planes = nullptr, const Overrides& params = {}) {
  testing::StageRunner<blobs::GrowBlobs> runner(params);
  runner.set_input("patches", Packet::make(patches));
  runner.set_input("points", Packet::make(points));
  if (planes != nullptr) runner.set_input("planes", Packet::make(*planes));
  runner.run();
  return runner.output<LabelImage>("blobs");
}

// Everything from a rendered scene: perfect patches -> planes -> blobs.
struct SceneRun {
  RenderedScene scene;
  PointImage points;
  PlanesResult planes;
  LabelImage blobs;
};

inline SceneRun run_scene(const SceneBuilder& builder, const Overrides& plane_params = {}) {
  SceneRun run;
  run.scene = builder.render();
  run.points = scene_points(run.scene);
  run.planes = run_planes(face_patches(run.scene, run.points), run.points, plane_params);
  run.blobs = run_blobs(run.planes.patches, run.points, &run.planes.planes);
  return run;
}

// Pixels of primitive `object` (1-based order of addition) and how many of them carry `label`.
inline std::int64_t count_where(const cv::Mat& object, int object_id, const cv::Mat& labels,
                                int label) {
  std::int64_t n = 0;
  for (int v = 0; v < object.rows; ++v) {
    for (int u = 0; u < object.cols; ++u) {
      if (object.at<int>(v, u) == object_id && labels.at<int>(v, u) == label) ++n;
    }
  }
  return n;
}

inline std::int64_t pixels_of(const cv::Mat& object, int object_id) {
  return cv::countNonZero(object == object_id);
}

// The label most of primitive `object`'s pixels carry (0 if most carry none).
inline int majority_label(const cv::Mat& object, int object_id, const cv::Mat& labels) {
  std::map<int, std::int64_t> votes;
  for (int v = 0; v < object.rows; ++v) {
    for (int u = 0; u < object.cols; ++u) {
      if (object.at<int>(v, u) == object_id) ++votes[labels.at<int>(v, u)];
    }
  }
  int best = 0;
  std::int64_t best_votes = -1;
  for (const auto& [label, n] : votes) {
    if (n > best_votes) {
      best = label;
      best_votes = n;
    }
  }
  return best;
}

}  // namespace facet::test
