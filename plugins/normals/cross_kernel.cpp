#include "normals/cross_kernel.hpp"

#include <algorithm>
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

// Pixels [x_begin, x_end) of one image row. Branch-free, so GCC vectorises it: an invalid (NaN)
// input propagates through the arithmetic into the squared length, and the centre pixel joins
// through `centre - centre` (0, or NaN when the centre is invalid). No -ffast-math anywhere, so
// NaN arithmetic is kept exactly. With kMarkMissing, missing[x - x_begin] is set to 1 where the
// pixel has depth but the triangle read a hole (0 elsewhere), for the one-sided pass.
template <bool kMetric, Triangle kTriangle, bool kMarkMissing>
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void cross_row(const RowTriple& rows, const float* cols, int r, int x_begin, int x_end, float* out,
               std::uint32_t* missing) {
  for (int x = x_begin; x < x_end; ++x) {
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
    if constexpr (kMarkMissing) {
      missing[x - x_begin] =
          static_cast<std::uint32_t>((length_sq != length_sq) & (centre == centre));
    }
    const float inv_length = 1.0F / std::sqrt(length_sq);
    out[3 * x + 0] = nx * inv_length;
    out[3 * x + 1] = ny * inv_length;
    out[3 * x + 2] = nz * inv_length;
  }
}

// The one-sided normal of pixel x (HoleNormals::one_sided): the first tangent pair whose pixels
// all have depth, tried right-below, left-below, right-above, left-above. Left NaN when none has.
template <bool kMetric>
void one_sided_normal(const RowTriple& rows, const float* cols, int r, int x, float* out) {
  const Vec3 p = lift<kMetric>(cols[x], rows.mid_factor, rows.mid[x]);
  const Vec3 east = lift<kMetric>(cols[x + r], rows.mid_factor, rows.mid[x + r]);
  const Vec3 west = lift<kMetric>(cols[x - r], rows.mid_factor, rows.mid[x - r]);
  const Vec3 south = lift<kMetric>(cols[x], rows.down_factor, rows.down[x]);
  const Vec3 north = lift<kMetric>(cols[x], rows.up_factor, rows.up[x]);
  const Vec3 horizontal[2] = {{east.x - p.x, east.y - p.y, east.z - p.z},
                              {p.x - west.x, p.y - west.y, p.z - west.z}};
  const Vec3 vertical[2] = {{south.x - p.x, south.y - p.y, south.z - p.z},
                            {p.x - north.x, p.y - north.y, p.z - north.z}};
  for (int i = 0; i < 4; ++i) {
    const Vec3& e1 = horizontal[i % 2];
    const Vec3& e2 = vertical[i / 2];
    float nx = e2.y * e1.z - e2.z * e1.y;
    float ny = e2.z * e1.x - e2.x * e1.z;
    float nz = e2.x * e1.y - e2.y * e1.x;
    const float length_sq = nx * nx + ny * ny + nz * nz;
    if (!(length_sq > 0.0F)) continue;  // NaN: a pixel of the pair has no depth
    if constexpr (kMetric) {
      if (nx * p.x + ny * p.y + nz * p.z > 0.0F) {
        nx = -nx;
        ny = -ny;
        nz = -nz;
      }
    }
    const float inv_length = 1.0F / std::sqrt(length_sq);
    out[3 * x + 0] = nx * inv_length;
    out[3 * x + 1] = ny * inv_length;
    out[3 * x + 2] = nz * inv_length;
    return;
  }
}

// The row with one-sided normals where the triangle read a hole: cross_row marks those pixels
// (a 32-bit mask, which keeps its loop vectorised; bytes did not) chunk by chunk.
template <bool kMetric, Triangle kTriangle>
void cross_row_one_sided(const RowTriple& rows, const float* cols, int r, int width, float* out) {
  constexpr int kChunk = 512;
  constexpr int kBlock = 16;
  std::uint32_t missing[kChunk];
  for (int begin = r; begin < width - r; begin += kChunk) {
    const int count = std::min(kChunk, width - r - begin);
    cross_row<kMetric, kTriangle, true>(rows, cols, r, begin, begin + count, out, missing);
    std::fill(missing + count, missing + kChunk, 0U);
    // Blocks of 16 without a marked pixel, most of them, are skipped with one vector OR.
    for (int block = 0; block < count; block += kBlock) {
      std::uint32_t any = 0;
      for (int i = 0; i < kBlock; ++i)
        any |= missing[block + i];
      if (any == 0) continue;
      for (int i = block; i < block + kBlock; ++i) {
        if (missing[i] != 0) one_sided_normal<kMetric>(rows, cols, r, begin + i, out);
      }
    }
  }
}

void fill_nan(float* out, int count) {
  for (int i = 0; i < count; ++i)
    out[i] = kNaN;
}

template <bool kMetric, Triangle kTriangle>
void cross_image_row(const cv::Mat& z, const PixelGrid& grid, int r, HoleNormals at_holes, int y,
                     float* out) {
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
  if (at_holes == HoleNormals::one_sided) {
    cross_row_one_sided<kMetric, kTriangle>(rows, grid.col_factor.data(), r, width, out);
  } else {
    cross_row<kMetric, kTriangle, false>(rows, grid.col_factor.data(), r, r, width - r, out,
                                         nullptr);
  }
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
    paper ? cross_image_row<true, Triangle::paper>(z, grid, r, options.at_holes, y, out)
          : cross_image_row<true, Triangle::centred>(z, grid, r, options.at_holes, y, out);
  } else {
    paper ? cross_image_row<false, Triangle::paper>(z, grid, r, options.at_holes, y, out)
          : cross_image_row<false, Triangle::centred>(z, grid, r, options.at_holes, y, out);
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
