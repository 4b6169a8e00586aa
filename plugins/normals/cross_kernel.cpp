#include "normals/cross_kernel.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace facet::normals {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Vec3 {
  float x, y, z;
};

// A pixel's point: (col_factor * s, row_factor * s, z), s = z in metric space, 1 in image space.
template <bool kMetric>
inline Vec3 lift(float col_factor, float row_factor, float z) {
  const float s = kMetric ? z : 1.0F;
  return {col_factor * s, row_factor * s, z};
}

// The rows a tangent pair reads, and their row factors.
struct RowTriple {
  const float* up;    // y - r
  const float* mid;   // y
  const float* down;  // y + r
  float up_factor, mid_factor, down_factor;
};

// One image row, x in [r, width - r). Branch-free, so GCC vectorises it: an invalid (NaN) input
// propagates through the arithmetic into the squared length, and the centre pixel joins through
// `centre - centre` (0, or NaN when the centre is invalid). No -ffast-math anywhere, so NaN
// arithmetic is kept exactly.
template <bool kMetric, Triangle kTriangle>
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void cross_row(const RowTriple& rows, const float* cols, int r, int width, float* out) {
  for (int x = r; x < width - r; ++x) {
    Vec3 e1;
    Vec3 e2;
    if constexpr (kTriangle == Triangle::paper) {
      const Vec3 a = lift<kMetric>(cols[x - r], rows.up_factor, rows.up[x - r]);
      const Vec3 b = lift<kMetric>(cols[x + r], rows.up_factor, rows.up[x + r]);
      const Vec3 c = lift<kMetric>(cols[x], rows.down_factor, rows.down[x]);
      e1 = {b.x - a.x, b.y - a.y, b.z - a.z};
      e2 = {c.x - a.x, c.y - a.y, c.z - a.z};
    } else {
      const Vec3 w = lift<kMetric>(cols[x - r], rows.mid_factor, rows.mid[x - r]);
      const Vec3 e = lift<kMetric>(cols[x + r], rows.mid_factor, rows.mid[x + r]);
      const Vec3 n = lift<kMetric>(cols[x], rows.up_factor, rows.up[x]);
      const Vec3 s = lift<kMetric>(cols[x], rows.down_factor, rows.down[x]);
      e1 = {e.x - w.x, e.y - w.y, e.z - w.z};
      e2 = {s.x - n.x, s.y - n.y, s.z - n.z};
    }
    // e2 x e1 = -(e1 x e2): with x right, y down, z away from the camera, e1 x e2 of a visible
    // surface points away from the camera, so the reversed product points towards it.
    float nx = e2.y * e1.z - e2.z * e1.y;
    float ny = e2.z * e1.x - e2.x * e1.z;
    float nz = e2.x * e1.y - e2.y * e1.x;
    const float centre = rows.mid[x];
    if constexpr (kMetric) {
      // Noise across a depth jump can still flip the product: enforce n . p < 0.
      const Vec3 p = lift<kMetric>(cols[x], rows.mid_factor, centre);
      const float flip = nx * p.x + ny * p.y + nz * p.z > 0.0F ? -1.0F : 1.0F;
      nx *= flip;
      ny *= flip;
      nz *= flip;
    }
    const float length_sq = nx * nx + ny * ny + nz * nz + (centre - centre);
    const float inv_length = 1.0F / std::sqrt(length_sq);
    out[3 * x + 0] = nx * inv_length;
    out[3 * x + 1] = ny * inv_length;
    out[3 * x + 2] = nz * inv_length;
  }
}

void fill_nan(float* out, int count) {
  for (int i = 0; i < count; ++i)
    out[i] = kNaN;
}

template <bool kMetric, Triangle kTriangle>
void cross_image_row(const cv::Mat& z, const PixelGrid& grid, int r, int y, float* out) {
  const int width = z.cols;
  const int height = z.rows;
  if (y < r || y >= height - r || width <= 2 * r) {
    fill_nan(out, 3 * width);
    return;
  }
  const RowTriple rows{z.ptr<float>(y - r),
                       z.ptr<float>(y),
                       z.ptr<float>(y + r),
                       grid.row_factor[static_cast<std::size_t>(y - r)],
                       grid.row_factor[static_cast<std::size_t>(y)],
                       grid.row_factor[static_cast<std::size_t>(y + r)]};
  fill_nan(out, 3 * r);
  cross_row<kMetric, kTriangle>(rows, grid.col_factor.data(), r, width, out);
  fill_nan(out + 3 * (width - r), 3 * r);
}

}  // namespace

void cross_normals_row(const cv::Mat& z, const PixelGrid& grid, const CrossOptions& options, int y,
                       float* out) {
  CV_Assert(z.type() == CV_32FC1);
  CV_Assert(grid.col_factor.size() == static_cast<std::size_t>(z.cols));
  CV_Assert(grid.row_factor.size() == static_cast<std::size_t>(z.rows));
  const int r = options.radius_px;
  const bool paper = options.triangle == Triangle::paper;
  if (grid.scale_by_z) {
    paper ? cross_image_row<true, Triangle::paper>(z, grid, r, y, out)
          : cross_image_row<true, Triangle::centred>(z, grid, r, y, out);
  } else {
    paper ? cross_image_row<false, Triangle::paper>(z, grid, r, y, out)
          : cross_image_row<false, Triangle::centred>(z, grid, r, y, out);
  }
}

void cross_normals(const cv::Mat& z, const PixelGrid& grid, const CrossOptions& options,
                   cv::Mat& normals, ParallelRunner* runner) {
  normals.create(z.rows, z.cols, CV_32FC3);
  constexpr std::int64_t kMinBandRows = 32;
  parallel_for(runner, z.rows, kMinBandRows, [&](std::int64_t begin, std::int64_t end) {
    for (auto y = static_cast<int>(begin); y < static_cast<int>(end); ++y)
      cross_normals_row(z, grid, options, y, normals.ptr<float>(y));
  });
}

}  // namespace facet::normals
