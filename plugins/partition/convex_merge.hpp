#pragma once
// Merging of adjacent surface patches whose junction is convex (the authors' later "cutfree"
// test): the surfaces of one object meet at outward edges, the surfaces of two touching objects
// at inward ones.

#include <cstdint>
#include <vector>

#include "facet/algo/disjoint_sets.hpp"
#include "facet/types/patches.hpp"
#include "partition/blob_segments.hpp"
#include "partition/segment_plane.hpp"

namespace facet::partition {

struct ConvexRule {
  double tolerance_m = 0.01;        // points closer than this to a plane are on it
  double min_behind_share = 0.9;    // share of a patch's points not in front of the other's plane
  double min_angle_deg = 30.0;      // mean normals closer than this: a step, not a convex edge
  std::int32_t min_patch_px = 100;  // smaller patches take part only as leftover pixels
};

// The convex-junction test of two patches with fitted planes: normals at least min_angle_deg
// apart (closer normals meet at a step, one surface in front of another, whichever side the
// points fall on), and each patch has at least min_behind_share of its points not more than
// tolerance_m in front of the other's plane.
bool is_convex_junction(const BlobSegments& points, const Segment& a, const FittedPlane& plane_a,
                        const Segment& b, const FittedPlane& plane_b, const ConvexRule& rule);

// Which patches touch, as per-patch neighbour lists (CSR), built once per frame.
class PatchNeighbours {
 public:
  void build(const PatchAdjacency& adjacency, std::int32_t max_patch);
  // Neighbours of `patch` with a larger id.
  const std::int32_t* begin(std::int32_t patch) const;
  const std::int32_t* end(std::int32_t patch) const;
  // The adjacency's contact_px of two patches; 0 when they do not touch.
  std::int32_t contact_px(std::int32_t a, std::int32_t b) const;

 private:
  std::vector<std::int32_t> offsets_;
  std::vector<std::int32_t> neighbours_;
  std::vector<std::int32_t> contacts_;  // contact_px of each entry of neighbours_
};

class ConvexMerger {
 public:
  explicit ConvexMerger(ConvexRule rule) : rule_(rule) {}

  // For a frame of another resolution (its pixel counts scaled).
  void set_rule(const ConvexRule& rule) { rule_ = rule; }

  // Groups the patches of `blob` and writes group ids next_id, next_id + 1, ... to labels[pixel]
  // of their points; leftover points stay 0. Returns the number of groups.
  std::int32_t merge(const BlobSegments& points, const BlobRange& blob,
                     const PatchNeighbours& neighbours, std::int32_t* labels, std::int32_t next_id);

  std::int64_t merges() const { return merges_; }
  void reset_counters() { merges_ = 0; }

 private:
  struct Node {
    std::int32_t segment = 0;
    FittedPlane plane;
  };
  ConvexRule rule_;
  std::vector<Node> nodes_;
  algo::DisjointSets groups_;                // nodes joined by a convex junction
  std::vector<std::int32_t> node_of_patch_;  // -1 outside the current blob
  std::vector<std::int32_t> group_id_;
  std::int64_t merges_ = 0;
};

}  // namespace facet::partition
