#include "normals/normal_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace facet::normals {
namespace {

// The normal at (u, v) averaged over its (2r+1)² window; false when it has none. The sum is not
// normalised: PairTest divides by the lengths.
bool normal_at(const cv::Mat& normals, int u, int v, int r, float* out) {
  const auto* centre = normals.ptr<float>(v) + 3 * u;
  if (!std::isfinite(centre[0])) return false;
  float sum[3] = {0.0F, 0.0F, 0.0F};
  const int y_end = std::min(normals.rows - 1, v + r);
  const int x_end = std::min(normals.cols - 1, u + r);
  for (int y = std::max(0, v - r); y <= y_end; ++y) {
    const auto* row = normals.ptr<float>(y);
    for (int x = std::max(0, u - r); x <= x_end; ++x) {
      const float* n = row + 3 * x;
      if (!std::isfinite(n[0])) continue;
      sum[0] += n[0];
      sum[1] += n[1];
      sum[2] += n[2];
    }
  }
  out[0] = sum[0];
  out[1] = sum[1];
  out[2] = sum[2];
  return true;
}

// |a · b| < min_cos |a| |b|, compared squared (min_cos > 0): the normals differ by more than the
// angle.
struct PairTest {
  float min_cos_squared = 0.0F;
  std::int64_t pairs = 0;
  std::int64_t noisy = 0;

  void add(const float* a, const float* b) {
    const float dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const float lengths_squared =
        (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    ++pairs;
    noisy += dot * dot < min_cos_squared * lengths_squared ? 1 : 0;
  }
};

}  // namespace

double noisy_pair_share(const cv::Mat& normals, const NoisyPairRule& rule, int smooth_radius_px) {
  CV_Assert(normals.type() == CV_32FC3);
  PairTest test;
  const double min_cos = std::cos(rule.angle_deg * std::numbers::pi / 180.0);
  test.min_cos_squared = static_cast<float>(min_cos * min_cos);
  const int step = rule.step_px;
  const int r = smooth_radius_px;
  if (r == 0) {
    // The normals as they are: read in place.
    for (int v = 0; v + step < normals.rows; v += rule.stride_px) {
      const auto* row = normals.ptr<float>(v);
      const auto* below = normals.ptr<float>(v + step);
      for (int u = 0; u + step < normals.cols; u += rule.stride_px) {
        const float* here = row + 3 * u;
        if (!std::isfinite(here[0])) continue;
        const float* right = row + 3 * (u + step);
        const float* down = below + 3 * u;
        if (std::isfinite(right[0])) test.add(here, right);
        if (std::isfinite(down[0])) test.add(here, down);
      }
    }
  } else {
    float here[3];
    float other[3];
    for (int v = 0; v + step < normals.rows; v += rule.stride_px) {
      for (int u = 0; u + step < normals.cols; u += rule.stride_px) {
        if (!normal_at(normals, u, v, r, here)) continue;
        if (normal_at(normals, u + step, v, r, other)) test.add(here, other);
        if (normal_at(normals, u, v + step, r, other)) test.add(here, other);
      }
    }
  }
  return test.pairs > 0 ? static_cast<double>(test.noisy) / static_cast<double>(test.pairs) : 0.0;
}

}  // namespace facet::normals
