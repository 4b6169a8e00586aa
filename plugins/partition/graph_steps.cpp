#include "partition/graph_steps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace facet::partition {

namespace {

// The smaller of the two centroids' distances from the other's plane: both faces must stand
// off the other's plane, so that two pieces of one face whose fitted normals differ a little
// (a tilt moves the far centroid, not the near one) are no step.
double step_offset_m(const FittedPlane& a, const FittedPlane& b) {
  const float a_off_b = std::abs(b.signed_distance_m(a.centroid_m.data()));
  const float b_off_a = std::abs(a.signed_distance_m(b.centroid_m.data()));
  return static_cast<double>(std::min(a_off_b, b_off_a));
}

}  // namespace

StepPairs find_step_pairs(const GraphNodes& graph, const TouchingNodes& touching,
                          const StepRule& rule) {
  StepPairs pairs;
  if (rule.min_offset_m <= 0.0) return pairs;
  const double min_cos = std::cos(rule.max_angle_deg * std::numbers::pi / 180.0);
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const GraphNode& a = graph.nodes[i];
    if (a.segment < 0 || !a.planar) continue;
    for (const std::int32_t j : touching[i]) {
      if (static_cast<std::size_t>(j) <= i) continue;
      const GraphNode& b = graph.nodes[static_cast<std::size_t>(j)];
      if (b.segment < 0 || !b.planar) continue;
      if (normal_cosine(a.plane, b.plane) < min_cos) continue;
      if (step_offset_m(a.plane, b.plane) < rule.min_offset_m) continue;
      pairs.emplace_back(static_cast<std::int32_t>(i), j);
    }
  }
  return pairs;
}

}  // namespace facet::partition
