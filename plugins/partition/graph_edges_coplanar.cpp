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

double distance_to(const FittedPlane& plane, const Eigen::Vector3f& point) {
  return static_cast<double>(plane.signed_distance_m(point.data()));
}

}  // namespace

void add_coplanar_edges(const GraphNodes& graph, const FrameImages& images,
                        const TouchingNodes& touching, const CoplanarRule& rule,
                        std::vector<GraphEdge>& edges) {
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
      const double a_off_b = std::abs(distance_to(b.plane, a.plane.centroid_m));
      const double b_off_a = std::abs(distance_to(a.plane, b.plane.centroid_m));
      if (std::max(a_off_b, b_off_a) > rule.max_distance_m) continue;
      // Touching patches meet at a step or a crease (the convex feature's), or, on one plane
      // within a blob, are one surface broken by an edge line.
      if (std::binary_search(touching_a.begin(), touching_a.end(), j)) {
        if (rule.touching_max_distance_m > 0.0 && a.blob == b.blob &&
            std::max(a_off_b, b_off_a) <= rule.touching_max_distance_m) {
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
    const GapEvidence gap = look_between(a, b, images, plane_between(a.plane, b.plane),
                                         rule.front_margin_m, rule.lines);
    if (!is_occluded(gap, rule.min_gap_px, rule.min_front_share)) continue;
    edges.push_back({pair.a, pair.b, EdgeFeature::coplanar});
  }
}

}  // namespace facet::partition
