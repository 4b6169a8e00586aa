#pragma once
// partition.graph: a face that spans the two bodies of a step pair. Two boxes side by side whose
// tops stand a step apart but whose fronts are flush show one front patch across both; once the
// step pair has put the tops in two objects (graph_steps.hpp), that front still went whole to
// one of them. Such a face meets both faces of the pair at a convex crease of comparable length,
// and the plane through the pair's seam, along their common normal, parts the two bodies: the
// face's points on each side of it join the object of the step face on that side.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "partition/blob_segments.hpp"
#include "partition/graph_edges.hpp"
#include "partition/graph_nodes.hpp"
#include "partition/graph_steps.hpp"

namespace facet::partition {

struct SpanSplitRule {
  bool enabled = true;
  // The face's shorter crease with the pair at least this share of its longer one: a corner
  // where one box's top meets the other box's front is a few contacts long, a face that spans
  // both boxes meets each along its side.
  double min_contact_ratio = 0.3;
  // Each side of the seam's plane holds at least this share of the face's points.
  double min_side_share = 0.2;
  // The seam's points spread along one line: the larger spread at least this many times the
  // second (a book on a book meets its neighbour around three sides, which is no line).
  double min_seam_elongation = 4.0;
};

// A node whose points go to two groups by the side of a plane: signed distance >= 0 to
// `group_in_front`, < 0 to `group_behind`.
struct SpanSplit {
  std::int32_t node = 0;
  Eigen::Vector3f normal = Eigen::Vector3f::UnitX();
  float offset_m = 0.0F;  // the plane is normal . x + offset_m = 0
  std::int32_t group_in_front = 0;
  std::int32_t group_behind = 0;

  bool in_front(float x, float y, float z) const {
    return normal.x() * x + normal.y() * y + normal.z() * z + offset_m >= 0.0F;
  }
  // The group of the node's point (x, y, z), metres.
  std::int32_t group_at(float x, float y, float z) const {
    return in_front(x, y, z) ? group_in_front : group_behind;
  }
};

// The splits of the faces that span a step pair whose two faces are in two groups. `group` is
// each node's group; `edges` the graph's edges with their contacts; `patches` the patch image
// (CV_32SC1) the seams are read from. At most one split per node (the first pair's).
std::vector<SpanSplit> find_span_splits(const BlobSegments& points, const GraphNodes& graph,
                                        const cv::Mat& patches, std::span<const GraphEdge> edges,
                                        const StepPairs& steps, std::span<const std::int32_t> group,
                                        const SpanSplitRule& rule);

}  // namespace facet::partition
