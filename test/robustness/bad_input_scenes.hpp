#pragma once
// Depth frames for the bad-input tests, ray-cast with test/support/synthetic_scene.hpp: a camera
// looking down at a table, boxes on it or floating, walls, a table seen edge-on, noise.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <opencv2/core.hpp>
#include <vector>

#include "majority_labels.hpp"
#include "synthetic_scene.hpp"
#include "tabletop_frame.hpp"

namespace facet::test {

// Depth as a sensor delivers it: uint16 millimetres, 0 where nothing was hit and beyond
// `max_range_m` (a depth camera of the Kinect kind measures up to a few metres).
inline cv::Mat depth_mm(const RenderedScene& scene, double max_range_m = 5.0) {
  cv::Mat out = cv::Mat::zeros(scene.depth_m.size(), CV_16UC1);
  for (int v = 0; v < out.rows; ++v) {
    for (int u = 0; u < out.cols; ++u) {
      const double z = scene.depth_m.at<float>(v, u);
      if (z > 0.0 && z <= max_range_m)
        out.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(std::lround(z * 1000.0));
    }
  }
  return out;
}

// Adds a box to a rendered frame (the nearer surface wins; its pixels get object id `id`),
// ray-casting only the pixels its corners project into, through a camera cut to that rectangle:
// a frame with hundreds of small boxes costs little more than one with a few.
inline void add_box(RenderedScene& scene, const Eigen::Isometry3d& pose,
                    const Eigen::Vector3d& half_m, int id) {
  const CameraIntrinsics& camera = scene.camera;
  double u_min = camera.width;
  double u_max = -1.0;
  double v_min = camera.height;
  double v_max = -1.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d local((corner & 1) != 0 ? half_m.x() : -half_m.x(),
                                (corner & 2) != 0 ? half_m.y() : -half_m.y(),
                                (corner & 4) != 0 ? half_m.z() : -half_m.z());
    const Eigen::Vector3d p = pose * local;
    if (p.z() <= 0.0) {  // partly behind the camera: cast every pixel
      u_min = v_min = 0.0;
      u_max = camera.width;
      v_max = camera.height;
      break;
    }
    const double u = camera.fx * p.x() / p.z() + camera.cx;
    const double v = camera.fy * p.y() / p.z() + camera.cy;
    u_min = std::min(u_min, u);
    u_max = std::max(u_max, u);
    v_min = std::min(v_min, v);
    v_max = std::max(v_max, v);
  }
  const cv::Rect window = cv::Rect(cv::Point(static_cast<int>(std::floor(u_min)) - 1,
                                             static_cast<int>(std::floor(v_min)) - 1),
                                   cv::Point(static_cast<int>(std::ceil(u_max)) + 2,
                                             static_cast<int>(std::ceil(v_max)) + 2)) &
                          cv::Rect(0, 0, camera.width, camera.height);
  if (window.empty()) return;
  CameraIntrinsics cut = camera;
  cut.cx -= window.x;
  cut.cy -= window.y;
  cut.width = window.width;
  cut.height = window.height;
  SceneBuilder builder(cut);
  builder.box(pose, half_m);
  const RenderedScene part = builder.render();
  for (int v = 0; v < window.height; ++v) {
    for (int u = 0; u < window.width; ++u) {
      const float z = part.depth_m.at<float>(v, u);
      float& here = scene.depth_m.at<float>(window.y + v, window.x + u);
      if (z <= 0.0F || (here > 0.0F && here <= z)) continue;
      here = z;
      scene.object.at<int>(window.y + v, window.x + u) = id;
    }
  }
}

// Gaussian depth noise of `sigma_mm` on the valid pixels, and a share `dropout` of all pixels set
// to 0 (no measurement), from a fixed seed.
inline cv::Mat with_noise(const cv::Mat& depth, double sigma_mm, double dropout,
                          std::uint64_t seed) {
  cv::RNG rng(seed);
  cv::Mat out = depth.clone();
  for (int v = 0; v < out.rows; ++v) {
    for (int u = 0; u < out.cols; ++u) {
      auto& z = out.at<std::uint16_t>(v, u);
      const double noisy = z + rng.gaussian(sigma_mm);
      const bool drop = rng.uniform(0.0, 1.0) < dropout;
      if (z == 0 || drop) {
        z = 0;
      } else {
        z = cv::saturate_cast<std::uint16_t>(std::max(1.0, noisy));
      }
    }
  }
  return out;
}

// The pixel count of each object id of `object` (index = id).
inline std::vector<std::int64_t> pixels_per_object(const cv::Mat& object, int count) {
  std::vector<std::int64_t> pixels(static_cast<std::size_t>(count) + 1, 0);
  for (int v = 0; v < object.rows; ++v) {
    for (int u = 0; u < object.cols; ++u) {
      const int id = object.at<int>(v, u);
      if (id > 0 && id <= count) ++pixels[static_cast<std::size_t>(id)];
    }
  }
  return pixels;
}

// How many of the rendered objects 1..count were found on their own: most of their pixels carry
// a label that no other rendered object's majority carries.
inline int objects_found_alone(const cv::Mat& object, int count, const cv::Mat& labels) {
  const std::vector<int> majority = majority_labels(object, count, labels);
  std::map<int, int> owners;
  for (int id = 1; id <= count; ++id) {
    if (majority[static_cast<std::size_t>(id)] != 0)
      ++owners[majority[static_cast<std::size_t>(id)]];
  }
  int alone = 0;
  for (int id = 1; id <= count; ++id) {
    const int label = majority[static_cast<std::size_t>(id)];
    if (label != 0 && owners[label] == 1) ++alone;
  }
  return alone;
}

}  // namespace facet::test
