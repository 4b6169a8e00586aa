#pragma once
// Test-side geometry for the edge and region-growing stages: 3D points and metric cross-product
// normals computed here, independent of the convert and normals plugins, and a reader for the
// bundled real frames. Also used by bench/surfaces_bench.cpp to prepare its input.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

#include "bundled_frames.hpp"
#include "facet/types/images.hpp"

namespace facet::test {

inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Back-projects depth (CV_32FC1 metres or CV_16UC1 millimetres; 0 or NaN = invalid; depth
// beyond max_depth_m is treated as invalid too) into CV_32FC3 points, NaN where invalid.
inline PointImage points_from_depth(const cv::Mat& depth, const CameraIntrinsics& camera,
                                    double max_depth_m = 10.0) {
  PointImage out;
  out.camera = camera;
  out.points = cv::Mat(depth.size(), CV_32FC3, cv::Scalar::all(kNaN));
  for (int v = 0; v < depth.rows; ++v) {
    for (int u = 0; u < depth.cols; ++u) {
      const double z = depth.type() == CV_16UC1 ? depth.at<std::uint16_t>(v, u) * 0.001
                                                : static_cast<double>(depth.at<float>(v, u));
      if (!(z > 0.0) || z > max_depth_m) continue;
      out.points.at<cv::Vec3f>(v, u) =
          cv::Vec3f(static_cast<float>((u - camera.cx) * z / camera.fx),
                    static_cast<float>((v - camera.cy) * z / camera.fy), static_cast<float>(z));
    }
  }
  return out;
}

// The paper's cross-product normal on metric points: A = (x-r, y-r), B = (x+r, y-r),
// C = (x, y+r), n = normalize((B-A) x (C-A)), turned towards the camera. NaN where a triangle
// corner is invalid or outside the image.
inline NormalImage cross_normals(const PointImage& points, int r = 2) {
  NormalImage out;
  static_cast<FrameHeader&>(out) = points;
  const cv::Mat& p = points.points;
  out.normals = cv::Mat(p.size(), CV_32FC3, cv::Scalar::all(kNaN));
  for (int y = r; y + r < p.rows; ++y) {
    for (int x = r; x + r < p.cols; ++x) {
      const cv::Vec3d a = p.at<cv::Vec3f>(y - r, x - r);
      const cv::Vec3d b = p.at<cv::Vec3f>(y - r, x + r);
      const cv::Vec3d c = p.at<cv::Vec3f>(y + r, x);
      cv::Vec3d n = (b - a).cross(c - a);
      const double length = cv::norm(n);
      if (!(length > 0.0)) continue;  // also false for NaN
      n /= length;
      const cv::Vec3d centre = p.at<cv::Vec3f>(y, x);
      if (std::isfinite(centre[2]) && n.dot(centre) > 0.0) n = -n;
      out.normals.at<cv::Vec3f>(y, x) = cv::Vec3f(n);
    }
  }
  return out;
}

// A bundled mOSD frame (uint16 mm PNG) as metric points and cross-product normals (r = 2).
struct RealFrame {
  PointImage points;
  NormalImage normals;
};

inline RealFrame load_mosd_frame(const std::filesystem::path& mosd_dir, const std::string& stem) {
  const DepthImage depth = bundled_mosd_frame(mosd_dir, stem);
  RealFrame frame;
  frame.points = points_from_depth(depth.depth, depth.camera);
  frame.normals = cross_normals(frame.points);
  return frame;
}

}  // namespace facet::test
