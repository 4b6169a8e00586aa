#include "partition/convex_merge.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace facet::partition {

bool is_convex_junction(const BlobSegments& points, const Segment& a, const FittedPlane& plane_a,
                        const Segment& b, const FittedPlane& plane_b, const ConvexRule& rule) {
  const double max_cos = std::cos(rule.min_angle_deg * std::numbers::pi / 180.0);
  if (normal_cosine(plane_a, plane_b) > max_cos) return false;
  return share_not_in_front(points, plane_a, b.begin, b.end, rule.tolerance_m) >=
             rule.min_behind_share &&
         share_not_in_front(points, plane_b, a.begin, a.end, rule.tolerance_m) >=
             rule.min_behind_share;
}

void PatchNeighbours::build(const PatchAdjacency& adjacency, std::int32_t max_patch) {
  std::int32_t top = std::max(max_patch, adjacency.count);
  for (const auto& [a, b] : adjacency.pairs)
    top = std::max({top, a, b});
  offsets_.assign(static_cast<std::size_t>(top) + 2, 0);
  for (const auto& [a, b] : adjacency.pairs) {
    if (a <= 0 || b <= 0 || a == b) continue;
    ++offsets_[static_cast<std::size_t>(std::min(a, b)) + 1];
  }
  for (std::size_t k = 1; k < offsets_.size(); ++k)
    offsets_[k] += offsets_[k - 1];
  neighbours_.assign(static_cast<std::size_t>(offsets_.back()), 0);
  contacts_.assign(neighbours_.size(), 0);
  // An adjacency without counts (a hand-made one) says only that the patches touch.
  const bool counted = adjacency.contact_px.size() == adjacency.pairs.size();
  std::vector<std::int32_t> fill(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t k = 0; k < adjacency.pairs.size(); ++k) {
    const auto [a, b] = adjacency.pairs[k];
    if (a <= 0 || b <= 0 || a == b) continue;
    const auto slot = static_cast<std::size_t>(fill[static_cast<std::size_t>(std::min(a, b))]++);
    neighbours_[slot] = std::max(a, b);
    contacts_[slot] = counted ? adjacency.contact_px[k] : 1;
  }
}

std::int32_t PatchNeighbours::contact_px(std::int32_t a, std::int32_t b) const {
  if (a > b) std::swap(a, b);
  const std::int32_t* first = begin(a);
  if (first == nullptr) return 0;
  const std::int32_t* last = end(a);
  const std::int32_t* it = std::find(first, last, b);
  return it == last ? 0 : contacts_[static_cast<std::size_t>(it - neighbours_.data())];
}

const std::int32_t* PatchNeighbours::begin(std::int32_t patch) const {
  if (patch < 0 || static_cast<std::size_t>(patch) + 1 >= offsets_.size()) return nullptr;
  return neighbours_.data() + offsets_[static_cast<std::size_t>(patch)];
}

const std::int32_t* PatchNeighbours::end(std::int32_t patch) const {
  if (patch < 0 || static_cast<std::size_t>(patch) + 1 >= offsets_.size()) return nullptr;
  return neighbours_.data() + offsets_[static_cast<std::size_t>(patch) + 1];
}

std::int32_t ConvexMerger::merge(const BlobSegments& points, const BlobRange& blob,
                                 const PatchNeighbours& neighbours, std::int32_t* labels,
                                 std::int32_t next_id) {
  nodes_.clear();
  if (node_of_patch_.size() < static_cast<std::size_t>(points.max_patch) + 1) {
    node_of_patch_.assign(static_cast<std::size_t>(points.max_patch) + 1, -1);
  }
  for (std::int32_t s = blob.segment_begin; s < blob.segment_end; ++s) {
    const Segment& segment = points.segments[static_cast<std::size_t>(s)];
    if (segment.patch == 0 || segment.size() < rule_.min_patch_px) continue;
    Node node{s, fit_plane(points, segment.begin, segment.end)};
    if (!node.plane.valid) continue;
    node_of_patch_[static_cast<std::size_t>(segment.patch)] =
        static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back(node);
  }
  const auto n = static_cast<std::int32_t>(nodes_.size());
  groups_.reset(static_cast<std::size_t>(n));

  for (std::int32_t i = 0; i < n; ++i) {
    const Node& a = nodes_[static_cast<std::size_t>(i)];
    const Segment& segment_a = points.segments[static_cast<std::size_t>(a.segment)];
    const std::int32_t* it = neighbours.begin(segment_a.patch);
    const std::int32_t* stop = neighbours.end(segment_a.patch);
    for (; it != nullptr && it != stop; ++it) {
      if (static_cast<std::size_t>(*it) >= node_of_patch_.size()) continue;
      const std::int32_t j = node_of_patch_[static_cast<std::size_t>(*it)];
      if (j < 0) continue;
      const Node& b = nodes_[static_cast<std::size_t>(j)];
      if (groups_.find(i) == groups_.find(j)) continue;  // skips the test, not only the union
      if (!is_convex_junction(points, segment_a, a.plane,
                              points.segments[static_cast<std::size_t>(b.segment)], b.plane,
                              rule_)) {
        continue;
      }
      groups_.unite(i, j);
      ++merges_;
    }
  }

  // Groups numbered in node order, which is ascending patch id: deterministic.
  group_id_.assign(static_cast<std::size_t>(n), -1);
  std::int32_t groups = 0;
  for (std::int32_t i = 0; i < n; ++i) {
    const std::int32_t root = groups_.find(i);
    std::int32_t& id = group_id_[static_cast<std::size_t>(root)];
    if (id < 0) id = next_id + groups++;
    const Segment& segment =
        points.segments[static_cast<std::size_t>(nodes_[static_cast<std::size_t>(i)].segment)];
    for (std::int32_t k = segment.begin; k < segment.end; ++k) {
      labels[points.pixel[static_cast<std::size_t>(k)]] = id;
    }
  }
  for (const Node& node : nodes_) {
    node_of_patch_[static_cast<std::size_t>(
        points.segments[static_cast<std::size_t>(node.segment)].patch)] = -1;
  }
  return groups;
}

}  // namespace facet::partition
