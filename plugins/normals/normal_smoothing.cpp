#include "normals/normal_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace facet::normals {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Adds one row of normals to the column sums; a NaN normal adds nothing.
// Splits one row of interleaved normals into planes: x, y, z (0 where invalid) and the valid
// count (1 or 0). Done once per pixel, so the window sums then read contiguous floats.
void split_row(const float* __restrict normals, int width, float* __restrict x_out,
               float* __restrict y_out, float* __restrict z_out, float* __restrict valid_out) {
  for (int u = 0; u < width; ++u) {
    const float x = normals[3 * u];
    const float y = normals[3 * u + 1];
    const float z = normals[3 * u + 2];
    // A normal is all-NaN or all-finite. (No named bool: GCC 12 then does not if-convert.)
    x_out[u] = x == x ? x : 0.0F;
    y_out[u] = x == x ? y : 0.0F;
    z_out[u] = x == x ? z : 0.0F;
    valid_out[u] = x == x ? 1.0F : 0.0F;
  }
}

void add_row(const float* __restrict row, int width, float* __restrict sum) {
  for (int u = 0; u < width; ++u)
    sum[u] += row[u];
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
  // Column sums are padded with r zeros on both sides, so the window sum over columns has the
  // same bounds at every x and vectorises.
  const auto padded = static_cast<std::size_t>(width + 2 * r);
  for (auto* buffer : {&sum_x_, &sum_y_, &sum_z_, &count_})
    buffer->assign(padded, 0.0F);
  for (auto* buffer : {&win_x_, &win_y_, &win_z_, &win_count_}) {
    buffer->resize(static_cast<std::size_t>(width));
  }

  // Planes x, y, z, valid, each height x width.
  const auto plane_size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  planes_.resize(4 * plane_size);
  const auto plane_row = [&](int plane, int v) {
    return planes_.data() + static_cast<std::size_t>(plane) * plane_size +
           static_cast<std::size_t>(v) * static_cast<std::size_t>(width);
  };
  for (int v = 0; v < height; ++v) {
    split_row(normals.ptr<float>(v), width, plane_row(0, v), plane_row(1, v), plane_row(2, v),
              plane_row(3, v));
  }

  std::vector<float>* sums[4] = {&sum_x_, &sum_y_, &sum_z_, &count_};
  std::vector<float>* windows[4] = {&win_x_, &win_y_, &win_z_, &win_count_};
  for (int y = 0; y < height; ++y) {
    for (int plane = 0; plane < 4; ++plane) {
      float* sum = sums[plane]->data() + r;
      std::fill(sum, sum + width, 0.0F);
      for (int v = std::max(0, y - r); v <= std::min(height - 1, y + r); ++v) {
        add_row(plane_row(plane, v), width, sum);
      }
      window_sum(sums[plane]->data(), width, r, windows[plane]->data());
    }
    finish_row(normals.ptr<float>(y), width, smoothed.ptr<float>(y));
  }
}

void NormalSmoother::window_sum(const float* __restrict padded, int width, int r,
                                float* __restrict out) {
  std::fill(out, out + width, 0.0F);
  for (int k = 0; k <= 2 * r; ++k) {
    for (int x = 0; x < width; ++x)
      out[x] += padded[x + k];
  }
}

void NormalSmoother::finish_row(const float* __restrict centre, int width,
                                float* __restrict out) const {
  const float* __restrict sx = win_x_.data();
  const float* __restrict sy = win_y_.data();
  const float* __restrict sz = win_z_.data();
  const float* __restrict count = win_count_.data();
  // The centre's own normal is in the sums, so count >= 1 whenever it is valid; an invalid
  // centre stays invalid through `centre - centre` (0, or NaN).
  if (renormalize_) {
    for (int x = 0; x < width; ++x) {
      const float guard = centre[3 * x] - centre[3 * x];
      const float scale = 1.0F / std::sqrt(sx[x] * sx[x] + sy[x] * sy[x] + sz[x] * sz[x]);
      out[3 * x + 0] = sx[x] * scale + guard;
      out[3 * x + 1] = sy[x] * scale + guard;
      out[3 * x + 2] = sz[x] * scale + guard;
    }
  } else {
    for (int x = 0; x < width; ++x) {
      const float guard = centre[3 * x] - centre[3 * x];
      const float scale = 1.0F / count[x];
      out[3 * x + 0] = sx[x] * scale + guard;
      out[3 * x + 1] = sy[x] * scale + guard;
      out[3 * x + 2] = sz[x] * scale + guard;
    }
  }
}

}  // namespace facet::normals
