#include "normals/window_moments.hpp"

#include <algorithm>

#include "normals/vector_clones.hpp"

namespace facet::normals {
namespace {

// One image row's points, as PixelGrid describes them.
struct RowPoints {
  const float* z = nullptr;
  double row_factor = 0.0;
};

// Pointers to the ten column sums. The arrays never overlap; `ivdep` tells GCC so.
struct ColumnSums {
  double* m[kMomentCount];
};

// Adds the moments of the entering row and subtracts those of the leaving row (if any) in one
// pass over the column sums. Branch-free: an invalid point (z NaN or infinite, so z - z is not
// 0) contributes zeros.
struct PointMoments {
  double w, qx, qy, qz, xx, xy, xz, yy, yz, zz;
};

template <bool kMetric>
inline PointMoments point_moments(float zf, float col_factor, double row_factor) {
  const bool valid = zf - zf == 0.0F;
  const double pz = valid ? static_cast<double>(zf) : 0.0;
  // Metric: (col * z, row * z, z); image: (u, v, z), the factors being u and v there.
  const double s = kMetric ? pz : 1.0;
  const double w = valid ? 1.0 : 0.0;
  const double px = static_cast<double>(col_factor) * s * w;
  const double py = row_factor * s * w;
  return {w, px, py, pz, px * px, px * py, px * pz, py * py, py * pz, pz * pz};
}

template <bool kMetric, bool kLeaving>
FACET_NORMALS_VECTOR_CLONES void update_row_moments(const RowPoints& entering,
                                                    const RowPoints& leaving,
                                                    const float* __restrict col_factor, int width,
                                                    ColumnSums sums) {
  double* __restrict sum[kMomentCount];
  for (int m = 0; m < kMomentCount; ++m)
    sum[m] = sums.m[m];
#pragma GCC ivdep
  for (int u = 0; u < width; ++u) {
    PointMoments d = point_moments<kMetric>(entering.z[u], col_factor[u], entering.row_factor);
    if constexpr (kLeaving) {
      const PointMoments o =
          point_moments<kMetric>(leaving.z[u], col_factor[u], leaving.row_factor);
      d = {d.w - o.w,   d.qx - o.qx, d.qy - o.qy, d.qz - o.qz, d.xx - o.xx,
           d.xy - o.xy, d.xz - o.xz, d.yy - o.yy, d.yz - o.yz, d.zz - o.zz};
    }
    sum[kCount][u] += d.w;
    sum[kX][u] += d.qx;
    sum[kY][u] += d.qy;
    sum[kZ][u] += d.qz;
    sum[kXX][u] += d.xx;
    sum[kXY][u] += d.xy;
    sum[kXZ][u] += d.xz;
    sum[kYY][u] += d.yy;
    sum[kYZ][u] += d.yz;
    sum[kZZ][u] += d.zz;
  }
}

// out[x] = sum of in[x - h .. x + h] for x in [h, width - h). One pass for the common windows
// (each output written once), k passes otherwise.
template <int kHalf>
FACET_NORMALS_VECTOR_CLONES void box_sum_row_fixed(const double* __restrict in, int width,
                                                   double* __restrict out) {
  for (int x = kHalf; x < width - kHalf; ++x) {
    double sum = in[x - kHalf];
    for (int k = 1 - kHalf; k <= kHalf; ++k)
      sum += in[x + k];
    out[x] = sum;
  }
}

FACET_NORMALS_VECTOR_CLONES void box_sum_row_any(const double* __restrict in, int width, int h,
                                                 double* __restrict out) {
  for (int x = h; x < width - h; ++x)
    out[x] = in[x - h] + in[x - h + 1];
  for (int k = 2 - h; k <= h; ++k) {
    for (int x = h; x < width - h; ++x)
      out[x] += in[x + k];
  }
}

void box_sum_row(const double* in, int width, int h, double* out) {
  switch (h) {
    case 1:
      return box_sum_row_fixed<1>(in, width, out);
    case 2:
      return box_sum_row_fixed<2>(in, width, out);
    case 3:
      return box_sum_row_fixed<3>(in, width, out);
    default:
      return box_sum_row_any(in, width, h, out);
  }
}

}  // namespace

void WindowMoments::start(const cv::Mat& z, const PixelGrid& grid, int window_px) {
  z_ = &z;
  grid_ = &grid;
  window_px_ = window_px;
  const auto width = static_cast<std::size_t>(z.cols);
  for (auto& sums : column_sums_)
    sums.assign(width, 0.0);
  for (auto& sums : window_sums_)
    sums.assign(width, 0.0);
  for (int v = 0; v < std::min(window_px, z.rows); ++v)
    update_columns(v, -1);
}

void WindowMoments::slide_to(int first_row) {
  update_columns(first_row + window_px_ - 1, first_row - 1);
}

void WindowMoments::update_columns(int entering_row, int leaving_row) {
  ColumnSums sums{};
  for (int m = 0; m < kMomentCount; ++m)
    sums.m[m] = column_sums_[static_cast<std::size_t>(m)].data();
  const auto row = [&](int v) {
    return RowPoints{z_->ptr<float>(v), grid_->row_factor[static_cast<std::size_t>(v)]};
  };
  const float* col_factor = grid_->col_factor.data();
  const int width = z_->cols;
  const RowPoints enter = row(entering_row);
  const bool metric = grid_->scale_by_z;
  if (leaving_row < 0) {
    metric ? update_row_moments<true, false>(enter, enter, col_factor, width, sums)
           : update_row_moments<false, false>(enter, enter, col_factor, width, sums);
  } else {
    const RowPoints leave = row(leaving_row);
    metric ? update_row_moments<true, true>(enter, leave, col_factor, width, sums)
           : update_row_moments<false, true>(enter, leave, col_factor, width, sums);
  }
}

void WindowMoments::sum_windows() {
  const int h = window_px_ / 2;
  const int width = z_->cols;
  for (int m = 0; m < kMomentCount; ++m) {
    box_sum_row(column_sums_[static_cast<std::size_t>(m)].data(), width, h,
                window_sums_[static_cast<std::size_t>(m)].data());
  }
}

}  // namespace facet::normals
