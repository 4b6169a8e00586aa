// partition.graph's coplanar feature: one planar surface seen in two pieces because something in
// front of it hides the middle (usually the two pieces are in different blobs).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "partition/graph_candidates.hpp"
#include "partition/graph_edges.hpp"
#include "partition/graph_gap.hpp"

namespace facet::partition {
namespace {

// Whether the body in the gap between nodes i and j stands on their surface: its patches (in the
// two pieces' blobs) and the patches touching them, but for the two pieces, each have at most a
// fifth of their pixels behind the surface. A can on a board ends at the board; a taller box
// between two equal boxes has a front face that reaches down to the table. A body without a
// patch gives no evidence.
bool body_stands_on(const FittedPlane& surface, const std::vector<std::int32_t>& body_patches,
                    std::int32_t i, std::int32_t j, const BlobSegments& points,
                    const GraphNodes& graph, const TouchingNodes& touching, double margin_m) {
  const GraphNode& a = graph.nodes[static_cast<std::size_t>(i)];
  const GraphNode& b = graph.nodes[static_cast<std::size_t>(j)];
  std::vector<std::int32_t> body;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    const GraphNode& node = graph.nodes[n];
    if ((node.blob == a.blob || node.blob == b.blob) &&
        std::binary_search(body_patches.begin(), body_patches.end(), node.patch)) {
      body.push_back(static_cast<std::int32_t>(n));
    }
  }
  if (body.empty()) return false;
  const std::size_t direct = body.size();
  for (std::size_t k = 0; k < direct; ++k) {
    const auto& near = touching[static_cast<std::size_t>(body[k])];
    body.insert(body.end(), near.begin(), near.end());
  }
  std::sort(body.begin(), body.end());
  body.erase(std::unique(body.begin(), body.end()), body.end());
  for (const std::int32_t n : body) {
    if (n == i || n == j) continue;
    const GraphNode& node = graph.nodes[static_cast<std::size_t>(n)];
    const Segment& segment = points.segments[static_cast<std::size_t>(node.segment)];
    if (5 * count_behind(points, surface, segment.begin, segment.end, margin_m) > node.size_px)
      return false;
  }
  return true;
}

}  // namespace

void add_coplanar_edges(const BlobSegments& points, const GraphNodes& graph,
                        const FrameImages& images, const TouchingNodes& touching,
                        const CoplanarRule& rule, std::vector<GraphEdge>& edges) {
  std::vector<std::int32_t> planar;
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const GraphNode& node = graph.nodes[i];
    if (node.segment >= 0 && node.planar) planar.push_back(static_cast<std::int32_t>(i));
  }
  const double min_cos = std::cos(rule.max_angle_deg * std::numbers::pi / 180.0);
  // The cheap tests (angle, plane distance, 3D gap) on every planar pair; the image lines only
  // for each patch's nearest few candidates.
  std::vector<CandidatePair> candidates;
  for (std::size_t x = 0; x < planar.size(); ++x) {
    const std::int32_t i = planar[x];
    const GraphNode& a = graph.nodes[static_cast<std::size_t>(i)];
    const auto& touching_a = touching[static_cast<std::size_t>(i)];
    for (std::size_t y = x + 1; y < planar.size(); ++y) {
      const std::int32_t j = planar[y];
      const GraphNode& b = graph.nodes[static_cast<std::size_t>(j)];
      if (rule.across_blobs_only && a.blob == b.blob) continue;
      if (normal_cosine(a.plane, b.plane) < min_cos) continue;
      const double offset_m = centroid_offset_m(a.plane, b.plane);
      if (offset_m > rule.max_distance_m) continue;
      // Touching patches meet at a step or a crease (the convex feature's), or, on one plane
      // within a blob, are one surface broken by an edge line.
      if (std::binary_search(touching_a.begin(), touching_a.end(), j)) {
        if (rule.touching_max_distance_m > 0.0 && a.blob == b.blob &&
            offset_m <= rule.touching_max_distance_m) {
          edges.push_back({i, j, EdgeFeature::coplanar});
        }
        continue;
      }
      const double gap_m = box_gap_m(a.bounds, b.bounds);
      if (gap_m > rule.max_gap_m) continue;
      candidates.push_back({i, j, gap_m});
    }
  }
  for (const CandidatePair& pair :
       nearest_pairs(std::move(candidates), static_cast<std::int32_t>(graph.nodes.size()),
                     rule.max_partners)) {
    const GraphNode& a = graph.nodes[static_cast<std::size_t>(pair.a)];
    const GraphNode& b = graph.nodes[static_cast<std::size_t>(pair.b)];
    const FittedPlane surface = plane_between(a.plane, b.plane);
    const GapEvidence gap =
        look_between(a, b, images, surface, rule.front_margin_m, rule.lines, rule.body_on_surface);
    const bool occluded = is_occluded(gap, rule.min_gap_px, rule.min_front_share) ||
                          (rule.body_on_surface &&
                           is_occluded_by_own_body(gap, rule.min_gap_px, rule.min_front_share) &&
                           body_stands_on(surface, gap.body_patches, pair.a, pair.b, points, graph,
                                          touching, rule.front_margin_m));
    if (!occluded) continue;
    edges.push_back({pair.a, pair.b, EdgeFeature::coplanar});
  }
}

}  // namespace facet::partition
