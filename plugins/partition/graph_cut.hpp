#pragma once
// The graph cut of partition.graph: connected groups of patches are objects, except that a weak
// bridge between two densely connected groups is cut.

#include <cstdint>
#include <span>
#include <vector>

#include "facet/algo/disjoint_sets.hpp"
#include "partition/graph_edges.hpp"
#include "partition/graph_steps.hpp"

namespace facet::partition {

struct CutRule {
  bool enabled = true;
  // A group is split along its cheapest cut while that cut costs less than this. An edge (i, j)
  // costs ½(1/deg_i + 1/deg_j), degrees counted within the group: a lone edge costs 1, an edge
  // of a node with one neighbour at least ½, so only bridges between groups of two or more
  // mutually joined patches are ever cut.
  double max_cost = 0.5;
  // Groups with more nodes are not cut (the cut is cubic in a group's size); a guard against
  // pathological input, far above a real object's patches.
  std::int32_t max_nodes = 120;
  // Cut only between dense groups: each side must hold a cycle (as many edges as nodes), e.g.
  // the three mutually convex faces of a box. A tree (a box's top joined to two front pieces
  // seen on both sides of an occluder) has bridges of cost under ½ but no dense group to
  // separate.
  bool needs_cycles = true;
};

class GraphCut {
 public:
  // Group of every node (0, 1, ... in order of each group's first node). Duplicate edges (two
  // features on one pair) count once. A group that still holds both nodes of a step pair is
  // then regrouped from its own edges, those of most contact first, leaving out every edge
  // that would join the two sides of a step pair: a corner where a top meets the other box's
  // front, or the top two flush boxes share, gives way before a face's long crease.
  const std::vector<std::int32_t>& groups(std::int32_t node_count, std::span<const GraphEdge> edges,
                                          const CutRule& rule, const StepPairs& steps = {});
  std::int64_t cuts() const { return cuts_; }
  // Groups regrouped for a step pair in the last call.
  std::int64_t step_separations() const { return step_separations_; }

 private:
  // Splits `members` (a connected set) by its minimum cut while the cut is cheap enough.
  void split(std::vector<std::int32_t> members, const CutRule& rule);
  // Stoer-Wagner minimum cut of the induced subgraph on `members`; returns the cut's cost and
  // marks one side in `side` (indices into members).
  double minimum_cut(const std::vector<std::int32_t>& members, std::vector<char>& side);
  // Whether the subgraph induced by `members` (connected) has a cycle.
  bool has_cycle(const std::vector<std::int32_t>& members);
  // Regroups each group that holds a step pair (see groups()).
  void separate_steps(std::span<const GraphEdge> edges, const StepPairs& steps);

  algo::DisjointSets groups_joined_;  // nodes joined by an edge: the connected components
  std::vector<std::vector<std::int32_t>> neighbours_;
  std::vector<std::int32_t> group_;
  std::vector<std::int32_t> local_;  // node -> index in the current members, -1 outside
  std::int32_t next_group_ = 0;
  std::int64_t cuts_ = 0;
  algo::DisjointSets regrouped_;  // the nodes of the groups separate_steps regroups
  std::int64_t step_separations_ = 0;
};

}  // namespace facet::partition
