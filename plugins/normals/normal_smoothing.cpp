#include "normals/normal_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace facet::normals {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Adds one row of normals to the column sums; a NaN normal adds nothing.
void add_row(const float* normals, int width, float* sum_x, float* sum_y, float* sum_z,
             float* count) {
  for (int u = 0; u < width; ++u) {
    const float x = normals[3 * u];
    const bool valid = x == x;  // a normal is all-NaN or all-finite
    sum_x[u] += valid ? x : 0.0F;
    sum_y[u] += valid ? normals[3 * u + 1] : 0.0F;
    sum_z[u] += valid ? normals[3 * u + 2] : 0.0F;
    count[u] += valid ? 1.0F : 0.0F;
  }
}

}  // namespace

NormalSmoother::NormalSmoother(int radius_px, bool renormalize)
    : radius_px_(radius_px), renormalize_(renormalize) {}

void NormalSmoother::apply(const cv::Mat& normals, cv::Mat& smoothed) {
  CV_Assert(normals.type() == CV_32FC3);
  CV_Assert(normals.data != smoothed.data);
  const int width = normals.cols;
  const int height = normals.rows;
  const int r = radius_px_;
  smoothed.create(height, width, CV_32FC3);
  const auto n = static_cast<std::size_t>(width);
  for (auto* buffer : {&sum_x_, &sum_y_, &sum_z_, &count_})
    buffer->resize(n);

  for (int y = 0; y < height; ++y) {
    std::fill(sum_x_.begin(), sum_x_.end(), 0.0F);
    std::fill(sum_y_.begin(), sum_y_.end(), 0.0F);
    std::fill(sum_z_.begin(), sum_z_.end(), 0.0F);
    std::fill(count_.begin(), count_.end(), 0.0F);
    for (int v = std::max(0, y - r); v <= std::min(height - 1, y + r); ++v) {
      add_row(normals.ptr<float>(v), width, sum_x_.data(), sum_y_.data(), sum_z_.data(),
              count_.data());
    }
    const auto* centre = normals.ptr<float>(y);
    auto* out = smoothed.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      float sx = 0.0F;
      float sy = 0.0F;
      float sz = 0.0F;
      float count = 0.0F;
      for (int u = std::max(0, x - r); u <= std::min(width - 1, x + r); ++u) {
        sx += sum_x_[static_cast<std::size_t>(u)];
        sy += sum_y_[static_cast<std::size_t>(u)];
        sz += sum_z_[static_cast<std::size_t>(u)];
        count += count_[static_cast<std::size_t>(u)];
      }
      // The centre's own normal is in the sums, so count >= 1 whenever it is valid; an invalid
      // centre stays invalid through `centre - centre`.
      const float guard = centre[3 * x] - centre[3 * x];
      const float scale =
          renormalize_ ? 1.0F / std::sqrt(sx * sx + sy * sy + sz * sz) : 1.0F / count;
      out[3 * x + 0] = sx * scale + guard;
      out[3 * x + 1] = sy * scale + guard;
      out[3 * x + 2] = sz * scale + guard;
    }
  }
}

}  // namespace facet::normals
