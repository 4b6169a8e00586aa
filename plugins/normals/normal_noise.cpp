#include "normals/normal_noise.hpp"

#include <cmath>
#include <cstdint>

namespace facet::normals {
namespace {

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

double noisy_pair_share(const cv::Mat& normals, const NoisyPairRule& rule) {
  CV_Assert(normals.type() == CV_32FC3);
  PairTest test;
  test.min_cos_squared = static_cast<float>(rule.edge_threshold * rule.edge_threshold);
  const int step = rule.step_px;
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
  return test.pairs > 0 ? static_cast<double>(test.noisy) / static_cast<double>(test.pairs) : 0.0;
}

}  // namespace facet::normals
