#include "planes/candidate_planes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include "facet/algo/label_runs.hpp"

namespace facet::planes {
namespace {

struct Candidate {
  std::int32_t patch = 0;
  std::int64_t size_px = 0;
  std::vector<float> points;  // x, y, z of each valid pixel of the patch

  Eigen::Vector3f centroid_m() const {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i + 2 < points.size(); i += 3)
      sum += Eigen::Vector3d(points[i], points[i + 1], points[i + 2]);
    const auto count = static_cast<double>(points.size() / 3);
    if (count == 0) return Eigen::Vector3f::Zero();
    return (sum / count).cast<float>();
  }
};

// Large patches, largest first (ties: lower id first), with at most max_points of their points
// each, evenly spread: every k-th point in raster order. A few thousand points fix a plane as
// well as the hundreds of thousands of a table top, at a fraction of the copying.
std::vector<Candidate> collect_candidates(const cv::Mat& labels, const cv::Mat& xyz,
                                          std::int32_t count, std::int64_t min_px,
                                          int max_candidates, std::int64_t max_points) {
  const auto* label = labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = labels.total();
  // Sizes count patch pixels (those of grow.surfaces all have a valid point); only the sampled
  // points are checked below. Both passes go by runs of one label along the raster: a patch's
  // pixels mostly come in long runs, and a counter per pixel was most of this kernel's time.
  std::vector<std::int64_t> size_px(static_cast<std::size_t>(count) + 1, 0);
  algo::for_each_label_run(label, total, [&](std::int32_t id, std::size_t begin, std::size_t end) {
    if (id > 0 && id <= count) size_px[id] += static_cast<std::int64_t>(end - begin);
  });
  std::vector<std::int32_t> ids;
  for (std::int32_t id = 1; id <= count; ++id) {
    if (size_px[id] >= min_px) ids.push_back(id);
  }
  std::stable_sort(ids.begin(), ids.end(),
                   [&](std::int32_t a, std::int32_t b) { return size_px[a] > size_px[b]; });
  if (ids.size() > static_cast<std::size_t>(max_candidates)) ids.resize(max_candidates);
  if (ids.empty()) return {};

  std::vector<Candidate> candidates(ids.size());
  // Per patch id: its candidate slot (-1 = none), the sampling step and the points to skip
  // before the next sample.
  std::vector<int> slot(static_cast<std::size_t>(count) + 1, -1);
  std::vector<std::int64_t> step(static_cast<std::size_t>(count) + 1, 1);
  std::vector<std::int64_t> skip(static_cast<std::size_t>(count) + 1, 0);
  for (std::size_t c = 0; c < ids.size(); ++c) {
    const std::int32_t id = ids[c];
    candidates[c].patch = id;
    candidates[c].size_px = size_px[id];
    step[id] = std::max<std::int64_t>(1, (size_px[id] + max_points - 1) / max_points);
    candidates[c].points.reserve(3 * static_cast<std::size_t>(size_px[id] / step[id] + 1));
    slot[id] = static_cast<int>(c);
  }
  algo::for_each_label_run(label, total, [&](std::int32_t id, std::size_t begin, std::size_t end) {
    if (id <= 0 || id > count || slot[id] < 0) return;
    auto& out = candidates[slot[id]].points;
    std::int64_t to_skip = skip[id];
    for (std::size_t i = begin; i < end; ++i) {
      const auto left_in_run = static_cast<std::int64_t>(end - i);
      if (to_skip >= left_in_run) {
        to_skip -= left_in_run;
        break;
      }
      i += static_cast<std::size_t>(to_skip);
      to_skip = 0;
      const float* p = point + 3 * i;
      if (!std::isfinite(p[2])) continue;  // the next point of the patch is taken instead
      to_skip = step[id] - 1;
      out.push_back(p[0]);
      out.push_back(p[1]);
      out.push_back(p[2]);
    }
    skip[id] = to_skip;
  });
  return candidates;
}

// Every k-th of `xyz`'s points (interleaved), at most kFootprintPoints of them.
std::vector<Eigen::Vector3f> footprint_of(std::span<const float> xyz) {
  const std::size_t count = xyz.size() / 3;
  const std::size_t step =
      std::max<std::size_t>(1, (count + kFootprintPoints - 1) / kFootprintPoints);
  std::vector<Eigen::Vector3f> footprint;
  footprint.reserve(count / step + 1);
  for (std::size_t i = 0; i < count; i += step)
    footprint.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  return footprint;
}

// The points of `candidate` farther than `distance_m` from `model`, and the centroid and the
// footprint of the others (those on the plane).
struct PlaneSplit {
  std::vector<float> off;
  Eigen::Vector3f on_centroid_m = Eigen::Vector3f::Zero();
  std::vector<Eigen::Vector3f> on_footprint_m;
};

PlaneSplit split_by_plane(const Candidate& candidate, const algo::Plane& model, float distance_m) {
  PlaneSplit split;
  std::vector<float> on;
  for (std::size_t i = 0; i + 2 < candidate.points.size(); i += 3) {
    const float* p = &candidate.points[i];
    auto& side = std::abs(model.signed_distance_m(p)) > distance_m ? split.off : on;
    side.insert(side.end(), p, p + 3);
  }
  Eigen::Vector3d on_sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i + 2 < on.size(); i += 3)
    on_sum += Eigen::Vector3d(on[i], on[i + 1], on[i + 2]);
  if (!on.empty())
    split.on_centroid_m = (on_sum / static_cast<double>(on.size() / 3)).cast<float>();
  split.on_footprint_m = footprint_of(on);
  return split;
}

// Two fits of one patch that are the same plane (within `angle_cos` and `distance_m` at the
// second fit's centroid): the second saw the first one's noisy fringe, not a plane of its own.
bool same_plane(const algo::Plane& a, const algo::Plane& b, const Eigen::Vector3f& b_centroid,
                float angle_cos, float distance_m) {
  return std::abs(a.normal.dot(b.normal)) >= angle_cos &&
         std::abs(a.signed_distance_m(b_centroid.data())) <= distance_m;
}

}  // namespace

std::vector<CandidatePlane> find_candidate_planes(const cv::Mat& labels, const cv::Mat& xyz,
                                                  std::int32_t count, const CandidateRule& rule,
                                                  const algo::RansacPlaneRule& fit_rule,
                                                  std::mt19937& rng) {
  std::vector<Candidate> candidates =
      collect_candidates(labels, xyz, count, rule.min_px, rule.max_candidates, rule.max_fit_points);
  std::vector<CandidatePlane> fitted;
  const float off_plane_m = rule.off_plane_m;
  for (auto& candidate : candidates) {
    Candidate part = std::move(candidate);
    std::optional<algo::Plane> previous;
    for (int plane = 0; plane < rule.planes_per_patch; ++plane) {
      const auto model = algo::ransac_plane(part.points, fit_rule, rng);
      if (!model) break;
      const Eigen::Vector3f centroid = part.centroid_m();
      if (previous && same_plane(*previous, *model, centroid, rule.same_plane_cos, off_plane_m))
        break;
      // The last plane allowed, or a patch whose off-plane points are too few for another
      // candidate, keeps the whole of what is left, size and centroid, as one plane per patch did.
      const bool last = plane + 1 == rule.planes_per_patch;
      PlaneSplit split = last ? PlaneSplit{} : split_by_plane(part, *model, off_plane_m);
      const auto sampled = static_cast<std::int64_t>(part.points.size() / 3);
      const std::int64_t off_px =
          sampled > 0 ? part.size_px * static_cast<std::int64_t>(split.off.size() / 3) / sampled
                      : 0;
      if (last || off_px < rule.min_px) {
        fitted.push_back({*model, part.size_px, centroid, footprint_of(part.points)});
        break;
      }
      // A patch that holds another plane: this plane takes its own points' size and centroid (the
      // levels of the scene model compare centroids with planes), not the whole patch's.
      fitted.push_back(
          {*model, part.size_px - off_px, split.on_centroid_m, std::move(split.on_footprint_m)});
      previous = model;
      part.points = std::move(split.off);
      part.size_px = off_px;
    }
  }
  // Largest first, as the candidates were: the table and the assignment order rely on it.
  std::stable_sort(
      fitted.begin(), fitted.end(),
      [](const CandidatePlane& a, const CandidatePlane& b) { return a.size_px > b.size_px; });
  return fitted;
}

}  // namespace facet::planes
