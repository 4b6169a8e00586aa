#include "convert/back_projection.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace facet::convert {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// One row: the per-column factor (u - cx) / fx is precomputed, so a pixel costs three
// multiplications and a range test, and the loop vectorises.
template <class DepthT>
void back_project_row(const DepthT* depth, const float* x_per_z, float y_per_z, float to_metres,
                      float min_m, float max_m, float* out, int width) {
  for (int u = 0; u < width; ++u) {
    const float z = static_cast<float>(depth[u]) * to_metres;
    // NaN fails both comparisons, so a NaN depth is invalid too.
    const bool valid = z > 0.0F && z >= min_m && z <= max_m;
    out[3 * u + 0] = valid ? x_per_z[u] * z : kNaN;
    out[3 * u + 1] = valid ? y_per_z * z : kNaN;
    out[3 * u + 2] = valid ? z : kNaN;
  }
}

}  // namespace

cv::Mat back_project(const cv::Mat& depth, const CameraIntrinsics& camera, DepthRange range) {
  if (depth.type() != CV_16UC1 && depth.type() != CV_32FC1) {
    throw std::invalid_argument("depth must be CV_16UC1 (mm) or CV_32FC1 (m)");
  }
  if (camera.fx <= 0.0 || camera.fy <= 0.0) {
    throw std::invalid_argument("camera intrinsics are missing (fx and fy must be positive)");
  }
  const int width = depth.cols;
  std::vector<float> x_per_z(static_cast<std::size_t>(width));
  for (int u = 0; u < width; ++u) {
    x_per_z[static_cast<std::size_t>(u)] = static_cast<float>((u - camera.cx) / camera.fx);
  }
  const float min_m = static_cast<float>(range.min_m);
  const float max_m =
      range.max_m > 0.0 ? static_cast<float>(range.max_m) : std::numeric_limits<float>::max();

  cv::Mat points(depth.rows, width, CV_32FC3);
  for (int v = 0; v < depth.rows; ++v) {
    const auto y_per_z = static_cast<float>((v - camera.cy) / camera.fy);
    auto* out = points.ptr<float>(v);
    if (depth.type() == CV_16UC1) {
      back_project_row(depth.ptr<std::uint16_t>(v), x_per_z.data(), y_per_z, 0.001F, min_m, max_m,
                       out, width);
    } else {
      back_project_row(depth.ptr<float>(v), x_per_z.data(), y_per_z, 1.0F, min_m, max_m, out,
                       width);
    }
  }
  return points;
}

}  // namespace facet::convert
