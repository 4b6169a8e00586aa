#include "normals/pca_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "normals/smallest_eigenvector.hpp"
#include "normals/smallest_eigenvector_closed_form.hpp"
#include "normals/vector_clones.hpp"

namespace facet::normals {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct WindowSums {
  const double* m[kMomentCount];
};

WindowSums window_sums_of(const WindowMoments& moments) {
  WindowSums sums{};
  for (int m = 0; m < kMomentCount; ++m)
    sums.m[m] = moments.window_sum(static_cast<Moment>(m));
  return sums;
}

// The window's covariance times n^2 (n the count of valid points): n S_xy - S_x S_y from the
// window sums, which needs no division; the eigenvectors do not depend on the scale.
inline SymmetricMatrix3 scaled_covariance_at(const WindowSums& s, int x) {
  const double n = s.m[kCount][x];
  const double sx = s.m[kX][x];
  const double sy = s.m[kY][x];
  const double sz = s.m[kZ][x];
  return {n * s.m[kXX][x] - sx * sx, n * s.m[kXY][x] - sx * sy, n * s.m[kXZ][x] - sx * sz,
          n * s.m[kYY][x] - sy * sy, n * s.m[kYZ][x] - sy * sz, n * s.m[kZZ][x] - sz * sz};
}

// The centre pixel's point; facing the camera means n . p < 0 in metric space and a negative
// third component in image space.
template <bool kMetric, class T>
inline T facing(T nx, T ny, T nz, T col_factor, T row_factor, T z) {
  return kMetric ? (nx * col_factor + ny * row_factor + nz) * z : nz;
}

// Per-row scratch of the closed-form eigenvectors, structure of arrays.
struct Directions {
  double* x;
  double* y;
  double* z;
};

// Eigenvectors of the windows at x in [h, width - h), NaN where the closed form does not trust
// its result (and where the window is empty). All double, so that the loop runs 4 pixels per
// AVX2 vector without spilling twice as many registers for a float-wide loop.
FACET_NORMALS_VECTOR_CLONES void closed_form_directions(WindowSums s, int h, int width,
                                                        Directions out) {
  double* __restrict dx = out.x;
  double* __restrict dy = out.y;
  double* __restrict dz = out.z;
#pragma GCC ivdep
  for (int x = h; x < width - h; ++x) {
    Direction3 v{};
    const bool trusted = closed_form_smallest_eigenvector(scaled_covariance_at(s, x), v);
    constexpr double kNaNd = std::numeric_limits<double>::quiet_NaN();
    dx[x] = trusted ? v.x : kNaNd;
    dy[x] = trusted ? v.y : kNaNd;
    dz[x] = trusted ? v.z : kNaNd;
  }
}

// Unit normals oriented towards the camera where the centre is valid and the window holds
// enough valid points, NaN elsewhere (and where the direction is NaN: left to the robust
// solver). Branch-free (selects only), so it vectorises across pixels.
template <bool kMetric>
FACET_NORMALS_VECTOR_CLONES void orient_row(const Directions& d, const double* __restrict count,
                                            const float* __restrict centre_z,
                                            const float* __restrict col_factor, float row_factor,
                                            double min_points, int h, int width,
                                            float* __restrict out) {
  const double* __restrict dx = d.x;
  const double* __restrict dy = d.y;
  const double* __restrict dz = d.z;
  for (int x = h; x < width - h; ++x) {
    const float z = centre_z[x];
    // `&`, not `&&`: no short-circuit branch, which would stop GCC from if-converting the loop.
    const bool has_normal = (z - z == 0.0F) & (count[x] >= min_points);
    // Normalised in single precision (cheaper): the output is float anyway.
    const auto vx = static_cast<float>(dx[x]);
    const auto vy = static_cast<float>(dy[x]);
    const auto vz = static_cast<float>(dz[x]);
    const float length = std::sqrt(vx * vx + vy * vy + vz * vz);
    const float towards = facing<kMetric>(vx, vy, vz, col_factor[x], row_factor, z) > 0.0F
                              ? -1.0F / length
                              : 1.0F / length;
    out[3 * x + 0] = has_normal ? vx * towards : kNaN;
    out[3 * x + 1] = has_normal ? vy * towards : kNaN;
    out[3 * x + 2] = has_normal ? vz * towards : kNaN;
  }
}

}  // namespace

PcaNormals::PcaNormals(PcaOptions options) : options_(options) {}

void PcaNormals::apply(const cv::Mat& z, const PixelGrid& grid, cv::Mat& normals) {
  CV_Assert(z.type() == CV_32FC1);
  const int width = z.cols;
  const int height = z.rows;
  const int h = options_.window_px / 2;
  const double min_points = std::max(3, options_.min_valid_points);
  normals.create(height, width, CV_32FC3);
  normals.setTo(cv::Scalar::all(kNaN));
  if (width <= 2 * h || height <= 2 * h) return;
  for (auto* buffer : {&direction_x_, &direction_y_, &direction_z_})
    buffer->resize(static_cast<std::size_t>(width));
  const Directions directions{direction_x_.data(), direction_y_.data(), direction_z_.data()};

  moments_.start(z, grid, options_.window_px);
  for (int y = h; y < height - h; ++y) {
    if (y > h) moments_.slide_to(y - h);
    moments_.sum_windows();
    const WindowSums sums = window_sums_of(moments_);
    closed_form_directions(sums, h, width, directions);
    const float* centre_z = z.ptr<float>(y);
    const float row_factor = grid.row_factor[static_cast<std::size_t>(y)];
    auto* out = normals.ptr<float>(y);
    if (grid.scale_by_z) {
      orient_row<true>(directions, sums.m[kCount], centre_z, grid.col_factor.data(), row_factor,
                       min_points, h, width, out);
    } else {
      orient_row<false>(directions, sums.m[kCount], centre_z, grid.col_factor.data(), row_factor,
                        min_points, h, width, out);
    }
    solve_untrusted(centre_z, grid, y, out);
  }
}

void PcaNormals::solve_untrusted(const float* centre_z, const PixelGrid& grid, int row,
                                 float* out) const {
  const WindowSums sums = window_sums_of(moments_);
  const double row_factor = grid.row_factor[static_cast<std::size_t>(row)];
  const double min_points = std::max(3, options_.min_valid_points);
  const int h = options_.window_px / 2;
  const int width = static_cast<int>(direction_x_.size());
  for (int x = h; x < width - h; ++x) {
    // Untrusted: a NaN direction where the pixel should have a normal.
    const double z = centre_z[x];
    const bool has_normal = z - z == 0.0 && sums.m[kCount][x] >= min_points;
    if (!has_normal || !std::isnan(direction_x_[static_cast<std::size_t>(x)])) continue;
    const SymmetricMatrix3 c = scaled_covariance_at(sums, x);
    Eigen::Matrix3d cov;
    cov << c.xx, c.xy, c.xz, c.xy, c.yy, c.yz, c.xz, c.yz, c.zz;
    const Eigen::Vector3d v = smallest_eigenvector(cov);
    const double f =
        grid.scale_by_z
            ? facing<true>(v.x(), v.y(), v.z(),
                           double{grid.col_factor[static_cast<std::size_t>(x)]}, row_factor, z)
            : facing<false>(v.x(), v.y(), v.z(), 0.0, 0.0, z);
    const double sign = f > 0.0 ? -1.0 : 1.0;
    out[3 * x + 0] = static_cast<float>(v.x() * sign);
    out[3 * x + 1] = static_cast<float>(v.y() * sign);
    out[3 * x + 2] = static_cast<float>(v.z() * sign);
  }
}

}  // namespace facet::normals
