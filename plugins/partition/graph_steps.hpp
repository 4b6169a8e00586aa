#pragma once
// partition.graph's steps: pairs of faces that no object holds together. A convex body shows
// each outward direction on one face only, so two planar patches that touch in the image, face
// the same way and lie on two parallel planes a step apart are faces of two bodies: the fronts
// of a box on a box, two boxes side by side with one set back, a book on a book. The edge
// features can still join such a pair through a third patch (a top that meets both fronts at
// a corner, a top the two boxes share when they stand flush); the groups that do are
// regrouped so that the pair ends in two objects (GraphCut).

#include <cstdint>
#include <utility>
#include <vector>

#include "partition/graph_edges.hpp"
#include "partition/graph_nodes.hpp"

namespace facet::partition {

struct StepRule {
  double min_offset_m = 0.0;    // each centroid at least this far from the other's plane; 0 = off
  double max_angle_deg = 15.0;  // normals at most this far apart: parallel
};

// Node index pairs (a < b), ascending.
using StepPairs = std::vector<std::pair<std::int32_t, std::int32_t>>;

// The step pairs among the planar nodes that touch in the image.
StepPairs find_step_pairs(const GraphNodes& graph, const TouchingNodes& touching,
                          const StepRule& rule);

}  // namespace facet::partition
