#include "partition/graph_steps.hpp"

#include <cmath>
#include <numbers>

namespace facet::partition {

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
      if (smaller_centroid_offset_m(a.plane, b.plane) < rule.min_offset_m) continue;
      pairs.emplace_back(static_cast<std::int32_t>(i), j);
    }
  }
  return pairs;
}

}  // namespace facet::partition
