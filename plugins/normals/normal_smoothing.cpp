#include "normals/normal_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "normals/vector_clones.hpp"

namespace facet::normals {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Splits one row of interleaved normals into planes: x, y, z (0 where invalid) and the valid
// count (1 or 0), so that the sums read contiguous floats. Two passes, a plain deinterleave and
// then the selects on contiguous floats: GCC 12 vectorises neither a select on the strided loads
// nor a self-comparison x == x, so validity is tested as |x| <= FLT_MAX (false for NaN).
FACET_NORMALS_VECTOR_CLONES void split_row(const float* __restrict normals, int width,
                                           float* __restrict x_out, float* __restrict y_out,
                                           float* __restrict z_out, float* __restrict valid_out) {
  for (int u = 0; u < width; ++u) {
    x_out[u] = normals[3 * u];
    y_out[u] = normals[3 * u + 1];
    z_out[u] = normals[3 * u + 2];
  }
  constexpr float kLargest = std::numeric_limits<float>::max();
  for (int u = 0; u < width; ++u) {
    // A normal is all-NaN or all-finite.
    const bool valid = std::abs(x_out[u]) <= kLargest;
    x_out[u] = valid ? x_out[u] : 0.0F;
    y_out[u] = valid ? y_out[u] : 0.0F;
    z_out[u] = valid ? z_out[u] : 0.0F;
    valid_out[u] = valid ? 1.0F : 0.0F;
  }
}

// sum = first (+ second) (+ third): the common windows of 1 to 3 rows in one pass.
FACET_NORMALS_VECTOR_CLONES void sum_rows(const float* __restrict first,
                                          const float* __restrict second,
                                          const float* __restrict third, int width,
                                          float* __restrict sum) {
  if (third != nullptr) {
    for (int u = 0; u < width; ++u)
      sum[u] = first[u] + second[u] + third[u];
  } else if (second != nullptr) {
    for (int u = 0; u < width; ++u)
      sum[u] = first[u] + second[u];
  } else {
    for (int u = 0; u < width; ++u)
      sum[u] = first[u];
  }
}

FACET_NORMALS_VECTOR_CLONES void add_row(const float* __restrict row, int width,
                                         float* __restrict sum) {
  for (int u = 0; u < width; ++u)
    sum[u] += row[u];
}

// out[x] = padded[x] + ... + padded[x + 2R]: the window over columns x - R .. x + R.
FACET_NORMALS_VECTOR_CLONES void sum_columns(const float* __restrict padded, int width, int r,
                                             float* __restrict out) {
  if (r == 1) {
    for (int x = 0; x < width; ++x)
      out[x] = padded[x] + padded[x + 1] + padded[x + 2];
    return;
  }
  for (int x = 0; x < width; ++x)
    out[x] = padded[x];
  for (int k = 1; k <= 2 * r; ++k) {
    for (int x = 0; x < width; ++x)
      out[x] += padded[x + k];
  }
}

// The centre's own normal is in the sums, so count >= 1 whenever it is valid; an invalid centre
// stays invalid through `guard` (0, or NaN).
FACET_NORMALS_VECTOR_CLONES void mean_row(const float* __restrict centre_valid,
                                          const float* __restrict sx, const float* __restrict sy,
                                          const float* __restrict sz, const float* __restrict count,
                                          int width, float* __restrict out) {
  for (int x = 0; x < width; ++x) {
    const float guard = centre_valid[x] != 0.0F ? 0.0F : kNaN;
    const float scale = 1.0F / count[x];
    out[3 * x + 0] = sx[x] * scale + guard;
    out[3 * x + 1] = sy[x] * scale + guard;
    out[3 * x + 2] = sz[x] * scale + guard;
  }
}

FACET_NORMALS_VECTOR_CLONES void direction_row(const float* __restrict centre_valid,
                                               const float* __restrict sx,
                                               const float* __restrict sy,
                                               const float* __restrict sz, int width,
                                               float* __restrict out) {
  for (int x = 0; x < width; ++x) {
    const float guard = centre_valid[x] != 0.0F ? 0.0F : kNaN;
    const float scale = 1.0F / std::sqrt(sx[x] * sx[x] + sy[x] * sy[x] + sz[x] * sz[x]);
    out[3 * x + 0] = sx[x] * scale + guard;
    out[3 * x + 1] = sy[x] * scale + guard;
    out[3 * x + 2] = sz[x] * scale + guard;
  }
}

}  // namespace

NormalSmoother::NormalSmoother(int radius_px, bool renormalize)
    : radius_px_(radius_px), renormalize_(renormalize) {}

float* NormalSmoother::ring_plane(int image_row, int plane) {
  const int slot = image_row % (2 * radius_px_ + 1);
  return ring_.data() + static_cast<std::size_t>(slot * kPlanes + plane) * width_;
}

void NormalSmoother::apply(const cv::Mat& normals, cv::Mat& smoothed) {
  CV_Assert(normals.type() == CV_32FC3);
  CV_Assert(normals.data != smoothed.data);
  apply(
      normals.rows, normals.cols,
      [&](int y, float* row) {
        const float* in = normals.ptr<float>(y);
        std::copy(in, in + 3 * normals.cols, row);
      },
      smoothed);
}

void NormalSmoother::apply(int height, int width, const RowSource& source, cv::Mat& smoothed) {
  width_ = width;
  const int r = radius_px_;
  smoothed.create(height, width, CV_32FC3);
  const auto w = static_cast<std::size_t>(width);
  const auto padded = w + 2 * static_cast<std::size_t>(r);
  incoming_.resize(3 * w);
  ring_.resize(static_cast<std::size_t>((2 * r + 1) * kPlanes) * w);
  column_sums_.assign(kPlanes * padded, 0.0F);
  window_sums_.resize(kPlanes * w);

  const auto take = [&](int v) {
    source(v, incoming_.data());
    split_row(incoming_.data(), width, ring_plane(v, 0), ring_plane(v, 1), ring_plane(v, 2),
              ring_plane(v, 3));
  };
  for (int v = 0; v < std::min(r, height); ++v)
    take(v);
  for (int y = 0; y < height; ++y) {
    if (y + r < height) take(y + r);
    const int first = std::max(0, y - r);
    const int last = std::min(height - 1, y + r);
    for (int plane = 0; plane < kPlanes; ++plane) {
      float* column = column_sums_.data() + plane * padded + r;
      const auto row = [&](int v) { return v <= last ? ring_plane(v, plane) : nullptr; };
      sum_rows(ring_plane(first, plane), row(first + 1), row(first + 2), width, column);
      for (int v = first + 3; v <= last; ++v)
        add_row(ring_plane(v, plane), width, column);
      sum_columns(column - r, width, r, window_sums_.data() + plane * w);
    }
    const float* sums = window_sums_.data();
    const float* centre_valid = ring_plane(y, 3);
    if (renormalize_) {
      direction_row(centre_valid, sums, sums + w, sums + 2 * w, width, smoothed.ptr<float>(y));
    } else {
      mean_row(centre_valid, sums, sums + w, sums + 2 * w, sums + 3 * w, width,
               smoothed.ptr<float>(y));
    }
  }
}

}  // namespace facet::normals
