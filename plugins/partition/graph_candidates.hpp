#pragma once
// Which non-adjacent node pairs the costly tests (image lines, quadric fits) look at: each node's
// nearest few partners, so that the cost grows with the number of patches, not its square.

#include <cstdint>
#include <vector>

namespace facet::partition {

struct CandidatePair {
  std::int32_t a = 0;  // node indices, a < b
  std::int32_t b = 0;
  double gap_m = 0.0;  // distance of their 3D boxes
};

// Keeps the pairs that are among the `max_per_node` nearest (by gap, then index) of either of
// their nodes, in ascending (a, b) order. The result does not depend on the input's order.
std::vector<CandidatePair> nearest_pairs(std::vector<CandidatePair> pairs, std::int32_t node_count,
                                         std::int32_t max_per_node);

}  // namespace facet::partition
