#include "partition/graph_candidates.hpp"

#include <algorithm>
#include <tuple>

namespace facet::partition {

std::vector<CandidatePair> nearest_pairs(std::vector<CandidatePair> pairs, std::int32_t node_count,
                                         std::int32_t max_per_node) {
  // Each pair once per end, ranked by (end, gap, other end): a stable total order.
  struct End {
    std::int32_t node;
    double gap_m;
    std::int32_t other;
    std::size_t pair;
  };
  std::vector<End> ends;
  ends.reserve(2 * pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ends.push_back({pairs[k].a, pairs[k].gap_m, pairs[k].b, k});
    ends.push_back({pairs[k].b, pairs[k].gap_m, pairs[k].a, k});
  }
  std::sort(ends.begin(), ends.end(), [](const End& x, const End& y) {
    return std::tie(x.node, x.gap_m, x.other) < std::tie(y.node, y.gap_m, y.other);
  });
  std::vector<char> keep(pairs.size(), 0);
  std::int32_t current = -1;
  std::int32_t rank = 0;
  for (const End& end : ends) {
    if (end.node < 0 || end.node >= node_count) continue;
    if (end.node != current) {
      current = end.node;
      rank = 0;
    }
    if (rank++ < max_per_node) keep[end.pair] = 1;
  }
  std::vector<CandidatePair> kept;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (keep[k] != 0) kept.push_back(pairs[k]);
  }
  std::sort(kept.begin(), kept.end(), [](const CandidatePair& x, const CandidatePair& y) {
    return std::tie(x.a, x.b) < std::tie(y.a, y.b);
  });
  return kept;
}

}  // namespace facet::partition
