#include "edges/normal_edge_score.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <stdexcept>

namespace facet::edges {
namespace {

// Only four of the eight directions need dot products: the product n(p)·n(p + k·d) of direction
// d at pixel p is also the product of direction -d at pixel p + k·d. So |dots| are computed for
// E, S, SE and SW, and W, N, NW, NE read them back at the shifted pixel.
struct Step {
  int dx;
  int dy;
};
constexpr std::array<Step, 4> kHalfDirections = {{{1, 0}, {0, 1}, {1, 1}, {-1, 1}}};
constexpr int kDirectionCount = 8;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Working memory: the |dot product| rows of the last R+1 image rows, for each of the four
// directions and each offset k = 1..R. Row y lives in slot y mod (R+1): combining row y needs
// the rows y-R..y (backward directions look up the products computed at p - k·d).
class DotRows {
 public:
  DotRows(std::vector<float>& storage, int reach_px, int width)
      : reach_px_(reach_px), width_(width) {
    const std::size_t rows = static_cast<std::size_t>(reach_px + 1) * kHalfDirections.size() *
                             static_cast<std::size_t>(reach_px);
    storage.resize(rows * static_cast<std::size_t>(width));
    data_ = storage.data();
  }
  float* row(int image_row, int direction, int k) const {
    const int slot = image_row % (reach_px_ + 1);
    const std::size_t index = (static_cast<std::size_t>(slot) * kHalfDirections.size() +
                               static_cast<std::size_t>(direction)) *
                                  static_cast<std::size_t>(reach_px_) +
                              static_cast<std::size_t>(k - 1);
    return data_ + index * static_cast<std::size_t>(width_);
  }

 private:
  int reach_px_;
  int width_;
  float* data_ = nullptr;
};

// Normals as three planes, so that every inner loop reads contiguous floats.
struct NormalPlanes {
  const float* x;
  const float* y;
  const float* z;
  int width;

  std::size_t offset(int row, int col) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(col);
  }
};

NormalPlanes split_planes(const cv::Mat& normals, std::vector<float>& storage) {
  const std::size_t pixels = normals.total();
  storage.resize(3 * pixels);
  float* px = storage.data();
  float* py = px + pixels;
  float* pz = py + pixels;
  cv::Mat planes[3] = {cv::Mat(normals.size(), CV_32FC1, px), cv::Mat(normals.size(), CV_32FC1, py),
                       cv::Mat(normals.size(), CV_32FC1, pz)};
  cv::split(normals, planes);
  return {px, py, pz, normals.cols};
}

__attribute__((target_clones("avx2", "default"))) void abs_dots(
    const float* __restrict ax, const float* __restrict ay, const float* __restrict az,
    const float* __restrict bx, const float* __restrict by, const float* __restrict bz,
    float* __restrict out, int count) {
  for (int i = 0; i < count; ++i) {
    out[i] = std::fabs(ax[i] * bx[i] + ay[i] * by[i] + az[i] * bz[i]);
  }
}

// |n(row, x) · n(row + k·dy, x + k·dx)| for every x where both pixels are in the image.
void compute_dot_rows(const NormalPlanes& n, int row, int reach_px, const DotRows& dots) {
  for (int d = 0; d < static_cast<int>(kHalfDirections.size()); ++d) {
    const Step step = kHalfDirections[static_cast<std::size_t>(d)];
    for (int k = 1; k <= reach_px; ++k) {
      const int x_begin = std::max(0, -k * step.dx);
      const int x_end = n.width - std::max(0, k * step.dx);
      const std::size_t a = n.offset(row, x_begin);
      const std::size_t b = n.offset(row + k * step.dy, x_begin + k * step.dx);
      abs_dots(n.x + a, n.y + a, n.z + a, n.x + b, n.y + b, n.z + b, dots.row(row, d, k) + x_begin,
               x_end - x_begin);
    }
  }
}

// Sum over k = 1..3 of one direction's |dots|, for one row.
__attribute__((target_clones("avx2", "default"))) void sum_three(const float* __restrict a,
                                                                 const float* __restrict b,
                                                                 const float* __restrict c,
                                                                 float* __restrict out, int count) {
  for (int i = 0; i < count; ++i)
    out[i] = a[i] + b[i] + c[i];
}

// Min or mean over the 8 direction sums (InvalidNeighbours::edge). A NaN anywhere among the 8·R
// products makes their total NaN, which becomes score 0. Every pointer is a separate restrict
// parameter so that the loop vectorises without run-time alias checks.
template <DirectionCombine Combine>
__attribute__((target_clones("avx2", "default"))) void combine_directions(
    const float* __restrict d0, const float* __restrict d1, const float* __restrict d2,
    const float* __restrict d3, const float* __restrict d4, const float* __restrict d5,
    const float* __restrict d6, const float* __restrict d7, float scale, float* __restrict out,
    int count) {
  for (int i = 0; i < count; ++i) {
    const float total = ((d0[i] + d1[i]) + (d2[i] + d3[i])) + ((d4[i] + d5[i]) + (d6[i] + d7[i]));
    float value = total;
    if constexpr (Combine == DirectionCombine::min) {
      value = std::min(std::min(std::min(d0[i], d1[i]), std::min(d2[i], d3[i])),
                       std::min(std::min(d4[i], d5[i]), std::min(d6[i], d7[i])));
    }
    // NaN becomes 0 through a bit mask: GCC 12 does not vectorise a floating-point select
    // here without -ffast-math ("control flow in loop"). total < infinity is false for NaN.
    const std::uint32_t keep = 0U - static_cast<std::uint32_t>(total < kInfinity);
    out[i] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(value * scale) & keep);
  }
}

// All bits set where `sum` is a number (a direction whose R products are all valid), none
// where it is NaN.
inline std::uint32_t valid_bits(float sum) {
  return 0U - static_cast<std::uint32_t>(sum < kInfinity);
}

// `value` where `mask` is set, `otherwise` elsewhere, as bit operations (see above).
inline float select_bits(std::uint32_t mask, float value, float otherwise) {
  return std::bit_cast<float>((std::bit_cast<std::uint32_t>(value) & mask) |
                              (std::bit_cast<std::uint32_t>(otherwise) & ~mask));
}

// `value` where `mask` is set, 0 elsewhere.
inline float and_bits(std::uint32_t mask, float value) {
  return std::bit_cast<float>(std::bit_cast<std::uint32_t>(value) & mask);
}

// Min or mean over the valid ones of the 8 direction sums (InvalidNeighbours::skip): a NaN sum
// is a direction that meets a pixel without a normal, and is left out. No valid direction (the
// pixel has no normal itself, or lies in a hole's middle) gives score 0. `scale` is 1 / R.
template <DirectionCombine Combine>
__attribute__((target_clones("avx2", "default"))) void combine_valid_directions(
    const float* __restrict d0, const float* __restrict d1, const float* __restrict d2,
    const float* __restrict d3, const float* __restrict d4, const float* __restrict d5,
    const float* __restrict d6, const float* __restrict d7, float scale, float* __restrict out,
    int count) {
  for (int i = 0; i < count; ++i) {
    const std::uint32_t v0 = valid_bits(d0[i]), v1 = valid_bits(d1[i]), v2 = valid_bits(d2[i]),
                        v3 = valid_bits(d3[i]), v4 = valid_bits(d4[i]), v5 = valid_bits(d5[i]),
                        v6 = valid_bits(d6[i]), v7 = valid_bits(d7[i]);
    const std::uint32_t any = v0 | v1 | v2 | v3 | v4 | v5 | v6 | v7;
    float value = 0.0F;
    if constexpr (Combine == DirectionCombine::min) {
      value = std::min(
          std::min(std::min(select_bits(v0, d0[i], kInfinity), select_bits(v1, d1[i], kInfinity)),
                   std::min(select_bits(v2, d2[i], kInfinity), select_bits(v3, d3[i], kInfinity))),
          std::min(std::min(select_bits(v4, d4[i], kInfinity), select_bits(v5, d5[i], kInfinity)),
                   std::min(select_bits(v6, d6[i], kInfinity), select_bits(v7, d7[i], kInfinity))));
      value *= scale;
    } else {
      // A select with 0 is a plain AND; the count of valid directions is the sum of the masks'
      // lowest bits, in integers.
      const float total = ((and_bits(v0, d0[i]) + and_bits(v1, d1[i])) +
                           (and_bits(v2, d2[i]) + and_bits(v3, d3[i]))) +
                          ((and_bits(v4, d4[i]) + and_bits(v5, d5[i])) +
                           (and_bits(v6, d6[i]) + and_bits(v7, d7[i])));
      const std::uint32_t directions = ((v0 & 1U) + (v1 & 1U) + (v2 & 1U) + (v3 & 1U)) +
                                       ((v4 & 1U) + (v5 & 1U) + (v6 & 1U) + (v7 & 1U));
      // Dividing by at least 1 keeps the value finite where no direction is valid; `any`
      // zeroes it then.
      value = total * scale / static_cast<float>(directions | (~any & 1U));
    }
    out[i] = and_bits(any, value);
  }
}

// Scores the rows [row_begin, row_end) of the image (those within R of the border stay 0). The
// products of the R rows above the first are computed first, so that bands of rows can be
// scored independently.
template <int R, DirectionCombine Combine, InvalidNeighbours Invalid>
void score_rows(const NormalPlanes& n, int height, int row_begin, int row_end, EdgeWorkspace& work,
                cv::Mat& score) {
  const int width = n.width;
  const int interior = width - 2 * R;
  const DotRows dots(work.dots, R, width);
  work.sums.resize(static_cast<std::size_t>(kDirectionCount) * static_cast<std::size_t>(width));
  float* direction_sums = work.sums.data();
  const int first = std::max(row_begin, R);
  const int last = std::min(row_end, height - R);
  for (int row = std::max(0, first - R); row < last; ++row) {
    compute_dot_rows(n, row, R, dots);
    if (row < first) continue;
    // Pointers to the products of pixel x = R, for the 8 directions: the forward ones at this
    // row, the backward ones where the pixel p - k·d stored them.
    // Per direction the sum over k, forward at this row, backward where the pixel p - k·d
    // stored it; for R = 1 the single product row itself.
    std::array<const float*, kDirectionCount> sums{};
    for (int d = 0; d < 4; ++d) {
      const Step step = kHalfDirections[static_cast<std::size_t>(d)];
      std::array<const float*, R> forward{};
      std::array<const float*, R> backward{};
      for (int k = 1; k <= R; ++k) {
        const auto ki = static_cast<std::size_t>(k - 1);
        forward[ki] = dots.row(row, d, k) + R;
        backward[ki] = dots.row(row - k * step.dy, d, k) + (R - k * step.dx);
      }
      if constexpr (R == 1) {
        sums[static_cast<std::size_t>(2 * d)] = forward[0];
        sums[static_cast<std::size_t>(2 * d + 1)] = backward[0];
      } else {
        float* forward_sum =
            direction_sums + static_cast<std::size_t>(2 * d) * static_cast<std::size_t>(width);
        float* backward_sum = forward_sum + width;
        sum_three(forward[0], forward[1], forward[2], forward_sum, interior);
        sum_three(backward[0], backward[1], backward[2], backward_sum, interior);
        sums[static_cast<std::size_t>(2 * d)] = forward_sum;
        sums[static_cast<std::size_t>(2 * d + 1)] = backward_sum;
      }
    }
    float* out = score.ptr<float>(row) + R;
    if constexpr (Invalid == InvalidNeighbours::skip) {
      // The mean divides by the number of valid directions itself.
      constexpr float kScale = 1.0F / static_cast<float>(R);
      combine_valid_directions<Combine>(sums[0], sums[1], sums[2], sums[3], sums[4], sums[5],
                                        sums[6], sums[7], kScale, out, interior);
    } else {
      constexpr float kScale = Combine == DirectionCombine::min
                                   ? 1.0F / static_cast<float>(R)
                                   : 1.0F / static_cast<float>(R * kDirectionCount);
      combine_directions<Combine>(sums[0], sums[1], sums[2], sums[3], sums[4], sums[5], sums[6],
                                  sums[7], kScale, out, interior);
    }
  }
}

template <int R, DirectionCombine Combine>
void score_rows_for(InvalidNeighbours invalid, const NormalPlanes& n, int height, int row_begin,
                    int row_end, EdgeWorkspace& work, cv::Mat& score) {
  if (invalid == InvalidNeighbours::skip) {
    score_rows<R, Combine, InvalidNeighbours::skip>(n, height, row_begin, row_end, work, score);
  } else {
    score_rows<R, Combine, InvalidNeighbours::edge>(n, height, row_begin, row_end, work, score);
  }
}

// Scores rows [row_begin, row_end) with the kernels compiled for this reach, combination and
// policy.
void score_band(int reach_px, DirectionCombine combine, InvalidNeighbours invalid,
                const NormalPlanes& planes, int height, int row_begin, int row_end,
                EdgeWorkspace& work, cv::Mat& score) {
  const bool take_min = combine == DirectionCombine::min;
  if (reach_px == 1) {
    if (take_min) {
      score_rows_for<1, DirectionCombine::min>(invalid, planes, height, row_begin, row_end, work,
                                               score);
    } else {
      score_rows_for<1, DirectionCombine::mean>(invalid, planes, height, row_begin, row_end, work,
                                                score);
    }
  } else if (take_min) {
    score_rows_for<3, DirectionCombine::min>(invalid, planes, height, row_begin, row_end, work,
                                             score);
  } else {
    score_rows_for<3, DirectionCombine::mean>(invalid, planes, height, row_begin, row_end, work,
                                              score);
  }
}

}  // namespace

NormalEdgeScorer::NormalEdgeScorer(int reach_px, DirectionCombine combine,
                                   InvalidNeighbours invalid)
    : reach_px_(reach_px), combine_(combine), invalid_(invalid) {
  if (reach_px != 1 && reach_px != 3) {
    throw std::invalid_argument("edge reach must be 1 or 3 pixels");
  }
}

cv::Mat NormalEdgeScorer::score(const cv::Mat& normals, ParallelRunner* runner) {
  if (normals.type() != CV_32FC3) {
    throw std::invalid_argument("normals must be CV_32FC3");
  }
  // Border pixels within reach are edges: they start at 0 and are never written.
  cv::Mat result = cv::Mat::zeros(normals.size(), CV_32FC1);
  if (normals.rows <= 2 * reach_px_ || normals.cols <= 2 * reach_px_) return result;

  const NormalPlanes planes = split_planes(normals, planes_);
  const int height = normals.rows;
  // Bands of at least 32 rows: each recomputes the R rows of products above it.
  constexpr std::int64_t kMinBandRows = 32;
  parallel_for(runner, height, kMinBandRows, [&](std::int64_t begin, std::int64_t end) {
    const auto work = workspaces_.lease();
    score_band(reach_px_, combine_, invalid_, planes, height, static_cast<int>(begin),
               static_cast<int>(end), *work, result);
  });
  return result;
}

cv::Mat edge_mask(const cv::Mat& score, float threshold) {
  cv::Mat mask;
  cv::compare(score, threshold, mask, cv::CMP_LE);  // 255 where true
  return mask;
}

}  // namespace facet::edges
