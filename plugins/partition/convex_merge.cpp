#include "partition/convex_merge.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace facet::partition {

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
  std::vector<std::int32_t> fill(offsets_.begin(), offsets_.end() - 1);
  for (const auto& [a, b] : adjacency.pairs) {
    if (a <= 0 || b <= 0 || a == b) continue;
    neighbours_[static_cast<std::size_t>(fill[static_cast<std::size_t>(std::min(a, b))]++)] =
        std::max(a, b);
  }
}

const std::int32_t* PatchNeighbours::begin(std::int32_t patch) const {
  if (patch < 0 || static_cast<std::size_t>(patch) + 1 >= offsets_.size()) return nullptr;
  return neighbours_.data() + offsets_[static_cast<std::size_t>(patch)];
}

const std::int32_t* PatchNeighbours::end(std::int32_t patch) const {
  if (patch < 0 || static_cast<std::size_t>(patch) + 1 >= offsets_.size()) return nullptr;
  return neighbours_.data() + offsets_[static_cast<std::size_t>(patch) + 1];
}

std::int32_t ConvexMerger::find(std::int32_t i) {
  while (parent_[static_cast<std::size_t>(i)] != i) {
    parent_[static_cast<std::size_t>(i)] =
        parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)])];
    i = parent_[static_cast<std::size_t>(i)];
  }
  return i;
}

double ConvexMerger::behind_share(const BlobSegments& points, const Node& a, const Node& b) const {
  const Segment& segment = points.segments[static_cast<std::size_t>(b.segment)];
  const float nx = a.plane.normal[0];
  const float ny = a.plane.normal[1];
  const float nz = a.plane.normal[2];
  const float d0 = a.plane.offset_m;
  const auto tol = static_cast<float>(rule_.tolerance_m);
  const float* x = points.x.data();
  const float* y = points.y.data();
  const float* z = points.z.data();
  std::int32_t in_front = 0;
  for (std::int32_t k = segment.begin; k < segment.end; ++k) {
    in_front += static_cast<std::int32_t>(nx * x[k] + ny * y[k] + nz * z[k] + d0 > tol);
  }
  return 1.0 - static_cast<double>(in_front) / static_cast<double>(segment.size());
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
  parent_.resize(static_cast<std::size_t>(n));
  for (std::int32_t i = 0; i < n; ++i)
    parent_[static_cast<std::size_t>(i)] = i;

  const double max_cos = std::cos(rule_.min_angle_deg * std::numbers::pi / 180.0);
  for (std::int32_t i = 0; i < n; ++i) {
    const Node& a = nodes_[static_cast<std::size_t>(i)];
    const std::int32_t patch = points.segments[static_cast<std::size_t>(a.segment)].patch;
    const std::int32_t* it = neighbours.begin(patch);
    const std::int32_t* stop = neighbours.end(patch);
    for (; it != nullptr && it != stop; ++it) {
      if (static_cast<std::size_t>(*it) >= node_of_patch_.size()) continue;
      const std::int32_t j = node_of_patch_[static_cast<std::size_t>(*it)];
      if (j < 0) continue;
      const Node& b = nodes_[static_cast<std::size_t>(j)];
      const double cos_angle = static_cast<double>(a.plane.normal[0] * b.plane.normal[0] +
                                                   a.plane.normal[1] * b.plane.normal[1] +
                                                   a.plane.normal[2] * b.plane.normal[2]);
      // Nearly parallel surfaces meet at a step (one object in front of another), whichever
      // side the points fall on.
      if (cos_angle > max_cos) continue;
      const std::int32_t ri = find(i);
      const std::int32_t rj = find(j);
      if (ri == rj) continue;
      if (behind_share(points, a, b) < rule_.min_behind_share) continue;
      if (behind_share(points, b, a) < rule_.min_behind_share) continue;
      parent_[static_cast<std::size_t>(std::max(ri, rj))] = std::min(ri, rj);
      ++merges_;
    }
  }

  // Groups numbered in node order, which is ascending patch id: deterministic.
  group_id_.assign(static_cast<std::size_t>(n), -1);
  std::int32_t groups = 0;
  for (std::int32_t i = 0; i < n; ++i) {
    const std::int32_t root = find(i);
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
