#pragma once
// Partition stage input from synthetic geometry: a tilted camera looks down at objects standing on
// an (unrendered) table; face ids become patches, chosen groups of objects become blobs, and the
// adjacency is the faces' 8-neighbour contacts. Results are compared with the object ids.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "facet/packet.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "synthetic_scene.hpp"

namespace facet::test {

// World frame on the table 1 m in front of a camera pitched down by 40 degrees: x right,
// y forward (away from the camera), z up.
class Tabletop {
 public:
  explicit Tabletop(double pitch_deg = 40.0) {
    const double a = pitch_deg * std::numbers::pi / 180.0;
    axes_.col(0) = Eigen::Vector3d::UnitX();
    axes_.col(1) = Eigen::Vector3d(0.0, -std::sin(a), std::cos(a));
    axes_.col(2) = Eigen::Vector3d(0.0, -std::cos(a), -std::sin(a));
    origin_ = Eigen::Vector3d(0.0, 0.0, 1.0);
  }
  // Pose of a body whose centre is at table coordinates (x, y) and height z, turned by yaw.
  Eigen::Isometry3d pose(double x_m, double y_m, double z_m, double yaw_deg = 0.0) const {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() =
        axes_ * Eigen::AngleAxisd(yaw_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ())
                    .toRotationMatrix();
    pose.translation() = origin_ + axes_ * Eigen::Vector3d(x_m, y_m, z_m);
    return pose;
  }
  // A box standing on the table (or on something of height base_m).
  Tabletop& box(double x_m, double y_m, const Eigen::Vector3d& half_m, double yaw_deg = 0.0,
                double base_m = 0.0) {
    builder_.box(pose(x_m, y_m, base_m + half_m.z(), yaw_deg), half_m);
    return *this;
  }
  Tabletop& cylinder(double x_m, double y_m, double radius_m, double half_height_m,
                     double base_m = 0.0) {
    builder_.cylinder(pose(x_m, y_m, base_m + half_height_m), radius_m, half_height_m);
    return *this;
  }
  // A cylinder lying on the table, its axis along x turned by yaw.
  Tabletop& lying_cylinder(double x_m, double y_m, double radius_m, double half_length_m,
                           double yaw_deg = 0.0) {
    Eigen::Isometry3d axis_along_x = pose(x_m, y_m, radius_m, yaw_deg);
    axis_along_x.linear() *=
        Eigen::AngleAxisd(std::numbers::pi / 2.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
    builder_.cylinder(axis_along_x, radius_m, half_length_m);
    return *this;
  }
  const SceneBuilder& builder() const { return builder_; }

 private:
  Eigen::Matrix3d axes_;
  Eigen::Vector3d origin_;
  SceneBuilder builder_;
};

struct PartitionInput {
  RenderedScene scene;
  LabelImage blobs;
  LabelImage patches;
  PatchAdjacency adjacency;
  PointImage points;
};

inline PointImage back_project(const RenderedScene& scene) {
  PointImage out;
  out.camera = scene.camera;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  out.points = cv::Mat(scene.depth_m.size(), CV_32FC3, cv::Scalar(nan, nan, nan));
  for (int v = 0; v < scene.depth_m.rows; ++v) {
    for (int u = 0; u < scene.depth_m.cols; ++u) {
      const float z = scene.depth_m.at<float>(v, u);
      if (z <= 0.0F) continue;
      out.points.at<cv::Vec3f>(v, u) =
          cv::Vec3f(static_cast<float>((u - scene.camera.cx) * z / scene.camera.fx),
                    static_cast<float>((v - scene.camera.cy) * z / scene.camera.fy), z);
    }
  }
  return out;
}

// Pairs of labels that are 8-neighbours, each once with a < b, sorted, with contact counts.
inline PatchAdjacency contacts_of(const cv::Mat& labels) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> pairs;
  for (int v = 0; v < labels.rows; ++v) {
    for (int u = 0; u < labels.cols; ++u) {
      const std::int32_t a = labels.at<std::int32_t>(v, u);
      if (a == 0) continue;
      const int du[4] = {1, -1, 0, 1};
      const int dv[4] = {0, 1, 1, 1};
      for (int k = 0; k < 4; ++k) {
        const int nu = u + du[k];
        const int nv = v + dv[k];
        if (nu < 0 || nu >= labels.cols || nv >= labels.rows) continue;
        const std::int32_t b = labels.at<std::int32_t>(nv, nu);
        if (b == 0 || b == a) continue;
        ++pairs[{std::min(a, b), std::max(a, b)}];
      }
    }
  }
  PatchAdjacency out;
  double max_id = 0.0;
  cv::minMaxLoc(labels, nullptr, &max_id);
  out.count = static_cast<std::int32_t>(max_id);
  for (const auto& [pair, count] : pairs) {
    out.pairs.push_back(pair);
    out.contact_px.push_back(count);
  }
  return out;
}

inline LabelImage label_image(const cv::Mat& labels) {
  LabelImage out;
  out.labels = labels.clone();
  double max_id = 0.0;
  cv::minMaxLoc(labels, nullptr, &max_id);
  out.count = static_cast<std::int32_t>(max_id);
  return out;
}

// Every object of the scene in one blob (the hard case: touching objects).
inline PartitionInput one_blob(const RenderedScene& scene) {
  PartitionInput input;
  input.scene = scene;
  cv::Mat blob = cv::Mat::zeros(scene.object.size(), CV_32SC1);
  blob.setTo(1, scene.object > 0);
  input.blobs = label_image(blob);
  input.patches = label_image(scene.face);
  input.adjacency = contacts_of(scene.face);
  input.points = back_project(scene);
  return input;
}

template <class Stage>
LabelImage run_partition(const PartitionInput& input,
                         const std::map<std::string, ParamValue>& params = {},
                         std::vector<Metric>* metrics = nullptr) {
  testing::StageRunner<Stage> runner(params);
  runner.set_input("blobs", Packet::make(input.blobs));
  runner.set_input("patches", Packet::make(input.patches));
  runner.set_input("adjacency", Packet::make(input.adjacency));
  runner.set_input("points", Packet::make(input.points));
  runner.run();
  if (metrics != nullptr) *metrics = runner.metrics();
  return runner.template output<LabelImage>("objects");
}

// Whether the objects match the scene's bodies one to one: every body has an object holding at
// least `min_share` of its pixels, that object's pixels are at least `min_share` that body's, and
// there are no other objects.
inline bool matches_bodies(const LabelImage& objects, const cv::Mat& bodies,
                           double min_share = 0.95) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::int64_t> overlap;
  std::map<std::int32_t, std::int64_t> body_px;
  std::map<std::int32_t, std::int64_t> object_px;
  for (int v = 0; v < bodies.rows; ++v) {
    for (int u = 0; u < bodies.cols; ++u) {
      const std::int32_t b = bodies.at<std::int32_t>(v, u);
      const std::int32_t o = objects.labels.at<std::int32_t>(v, u);
      if (b > 0) ++body_px[b];
      if (o > 0) ++object_px[o];
      if (b > 0 && o > 0) ++overlap[{b, o}];
    }
  }
  if (object_px.size() != body_px.size()) return false;
  std::set<std::int32_t> used;
  for (const auto& [body, px] : body_px) {
    bool found = false;
    for (const auto& [pair, count] : overlap) {
      if (pair.first != body) continue;
      const double share_of_body = static_cast<double>(count) / static_cast<double>(px);
      const double share_of_object =
          static_cast<double>(count) / static_cast<double>(object_px[pair.second]);
      if (share_of_body >= min_share && share_of_object >= min_share &&
          used.insert(pair.second).second) {
        found = true;
      }
    }
    if (!found) return false;
  }
  return true;
}

inline double metric_value(const std::vector<Metric>& metrics, const std::string& name) {
  for (const auto& m : metrics) {
    if (m.name == name) return m.value;
  }
  return -1.0;
}

}  // namespace facet::test
