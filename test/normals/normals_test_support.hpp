#pragma once
// Helpers shared by the normals tests: running a stage on a depth image, angles, the bundled
// real frame, and the analytic normals of a plane in each space.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

#include "bundled_frames.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "synthetic_scene.hpp"

namespace facet::test {

using StageParams = std::map<std::string, ParamValue>;

// Runs a normals stage on one depth image and returns a copy of its normals.
template <class StageT>
cv::Mat run_normals(const DepthImage& depth, const StageParams& params = {}) {
  facet::testing::StageRunner<StageT> runner(params);
  runner.set_input("depth", Packet::make(depth));
  runner.run();
  return runner.template output<NormalImage>("normals").normals.clone();
}

inline Eigen::Vector3d normal_at(const cv::Mat& normals, int v, int u) {
  const auto& n = normals.at<cv::Vec3f>(v, u);
  return {n[0], n[1], n[2]};
}

inline bool has_normal(const cv::Mat& normals, int v, int u) {
  const auto& n = normals.at<cv::Vec3f>(v, u);
  return std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]);
}

inline bool is_all_nan(const cv::Mat& normals, int v, int u) {
  const auto& n = normals.at<cv::Vec3f>(v, u);
  return std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2]);
}

inline double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double c = std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::numbers::pi;
}

// A camera-facing unit normal tilted by `tilt_deg` from the optical axis, about an axis in the
// image plane at `azimuth_deg`.
inline Eigen::Vector3d tilted_normal(double tilt_deg, double azimuth_deg) {
  const double t = tilt_deg * std::numbers::pi / 180.0;
  const double a = azimuth_deg * std::numbers::pi / 180.0;
  return {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), -std::cos(t)};
}

// The bundled real frame (Kinect-type sensor, 640x480, uint16 mm) with its intrinsics.
inline DepthImage real_frame(const std::string& stem = "learn0") {
  return bundled_mosd_frame(std::filesystem::path(FACET_TEST_DATA_DIR) / "mosd", stem);
}

// Kinect v1 raw disparity of a depth in mm, as the image space's 'disparity' unit defines it.
inline double raw_disparity(double depth_mm) {
  return (3.3309495161 - 1046.0 / depth_mm) / 0.0030711016;
}

// The plane n . P = d (camera frame, metres) seen at pixel (u, v): 1 / Z is affine in (u, v),
//   1 / Z = (n_x (u - cx) / fx + n_y (v - cy) / fy + n_z) / d.
struct PlaneView {
  Eigen::Vector3d n;
  double d;
  CameraIntrinsics camera;

  double inverse_depth_m(double u, double v) const {
    return (n.x() * (u - camera.cx) / camera.fx + n.y() * (v - camera.cy) / camera.fy + n.z()) / d;
  }
  // Image-space normal for z = disparity * scale: the disparity is affine in 1 / Z, so the plane
  // stays a plane there, with gradient (dz/du, dz/dv); its camera-facing normal is
  // (dz/du, dz/dv, -1), normalised.
  Eigen::Vector3d disparity_space_normal(double scale) const {
    const double k = -scale * 1046.0 / 0.0030711016 / 1000.0;  // d raw / d (1 / Z_m)
    const double du = k * n.x() / (camera.fx * d);
    const double dv = k * n.y() / (camera.fy * d);
    return Eigen::Vector3d(du, dv, -1.0).normalized();
  }
  // Image-space normal for z = depth in mm (the plane is curved there): from the gradient at
  // (u, v).
  Eigen::Vector3d mm_space_normal(double u, double v) const {
    const double w = inverse_depth_m(u, v);
    const double du = -1000.0 * (n.x() / camera.fx / d) / (w * w);
    const double dv = -1000.0 * (n.y() / camera.fy / d) / (w * w);
    return Eigen::Vector3d(du, dv, -1.0).normalized();
  }
};

}  // namespace facet::test
