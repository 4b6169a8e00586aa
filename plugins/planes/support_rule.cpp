#include "planes/support_rule.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace facet::planes {
namespace {

// Per sampled valid pixel: bit i set when the pixel lies on candidate i, resp. behind it.
struct SampleBits {
  std::vector<std::uint32_t> on;
  std::vector<std::uint32_t> behind;
};

SampleBits classify_samples(const cv::Mat& points, const std::vector<algo::Plane>& candidates,
                            const SupportRule& rule) {
  SampleBits bits;
  const int stride = std::max(1, rule.sample_stride_px);
  const auto samples = static_cast<std::size_t>((points.rows + stride - 1) / stride) *
                       static_cast<std::size_t>((points.cols + stride - 1) / stride);
  bits.on.reserve(samples);
  bits.behind.reserve(samples);
  for (int row = 0; row < points.rows; row += stride) {
    const auto* xyz = points.ptr<float>(row);
    for (int col = 0; col < points.cols; col += stride) {
      const float* p = xyz + 3 * col;
      if (!std::isfinite(p[2])) continue;
      std::uint32_t on = 0;
      std::uint32_t behind = 0;
      for (std::size_t i = 0; i < candidates.size(); ++i) {
        const float d = candidates[i].signed_distance_m(p);
        if (std::abs(d) <= rule.inlier_distance_m) on |= 1U << i;
        if (d < -rule.behind_margin_m) behind |= 1U << i;
      }
      bits.on.push_back(on);
      bits.behind.push_back(behind);
    }
  }
  return bits;
}

}  // namespace

std::vector<CandidateEvidence> decide_support(const cv::Mat& points,
                                              const std::vector<algo::Plane>& candidates, int table,
                                              const std::vector<CandidateRole>& roles,
                                              const Eigen::Vector3f& up, const SupportRule& rule) {
  if (candidates.size() > 32) throw std::invalid_argument("at most 32 candidate planes");
  std::vector<CandidateEvidence> evidence(candidates.size());
  if (candidates.empty()) return evidence;
  const SampleBits bits = classify_samples(points, candidates, rule);
  const auto valid = static_cast<double>(bits.on.size());
  if (valid == 0.0) return evidence;

  for (std::size_t i = 0; i < candidates.size(); ++i) {
    std::size_t on = 0;
    for (const std::uint32_t mask : bits.on)
      on += (mask >> i) & 1U;
    evidence[i].view_fraction = static_cast<double>(on) / valid;
  }

  // An object face stands on the table: part of the table lies behind it (a box top has
  // all of it behind, a box front the table part beyond the box). Walls and the floor have the
  // table in front of them.
  if (table >= 0) {
    const std::uint32_t table_bit = 1U << static_cast<unsigned>(table);
    std::size_t table_on = 0;
    for (const std::uint32_t mask : bits.on)
      table_on += (mask & table_bit) != 0U ? 1 : 0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      std::size_t behind = 0;
      for (std::size_t s = 0; s < bits.on.size(); ++s) {
        if ((bits.on[s] & table_bit) != 0U) behind += (bits.behind[s] >> i) & 1U;
      }
      evidence[i].support_behind_fraction =
          table_on > 0 ? static_cast<double>(behind) / static_cast<double>(table_on) : 0.0;
    }
  }

  std::uint32_t accepted = 0;
  std::uint32_t never = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (roles[i] == CandidateRole::table) accepted |= 1U << i;
    if (roles[i] == CandidateRole::object_top) never |= 1U << i;
  }
  if (table >= 0) accepted |= 1U << static_cast<unsigned>(table);
  // Each round may accept planes (never reject one), so this ends after at most one round per
  // candidate.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const std::uint32_t self = 1U << i;
      if (((accepted | never) & self) != 0U) continue;
      const std::uint32_t removed = accepted | self;
      std::size_t objects = 0;
      std::size_t behind = 0;
      for (std::size_t s = 0; s < bits.on.size(); ++s) {
        if ((bits.on[s] & removed) != 0U) continue;
        ++objects;
        behind += (bits.behind[s] >> i) & 1U;
      }
      const double denominator =
          std::max(static_cast<double>(objects), rule.min_object_fraction * valid);
      evidence[i].behind_fraction = static_cast<double>(behind) / denominator;
      // A large horizontal plane above a floor is a table, not a box top; a large
      // vertical face that stands on the table is still an object (a big box close up).
      const bool large_table = evidence[i].view_fraction >= rule.large_view_fraction &&
                               std::abs(candidates[i].normal.dot(up)) >= rule.min_cos_horizontal;
      const bool stands_on_support =
          evidence[i].support_behind_fraction > rule.max_support_behind_fraction && !large_table;
      if (!stands_on_support && evidence[i].view_fraction >= rule.min_view_fraction &&
          evidence[i].behind_fraction <= rule.max_behind_fraction) {
        accepted |= self;
        changed = true;
      }
    }
  }
  for (std::size_t i = 0; i < candidates.size(); ++i)
    evidence[i].accepted = ((accepted >> i) & 1U) != 0U;
  return evidence;
}

}  // namespace facet::planes
