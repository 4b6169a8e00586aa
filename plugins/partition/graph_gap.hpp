#pragma once
// What lies between two patches in the image: the evidence that an occluder hides the part of
// one surface that would join them (partition.graph's coplanar feature).

#include <cstdint>
#include <vector>

#include "partition/graph_edges.hpp"
#include "partition/graph_nodes.hpp"
#include "partition/segment_plane.hpp"

namespace facet::partition {

struct GapEvidence {
  std::int32_t front_px = 0;  // valid gap pixels more than the margin in front of the surface, of
                              // a blob other than the two patches'
  std::int32_t own_front_px = 0;   // ... of one of the two patches' own blobs (a body touching)
  std::int32_t other_px = 0;       // valid gap pixels on it or behind it
  std::int32_t invalid_px = 0;     // gap pixels without a point: neither (not counted in shares)
  std::int32_t lines_through = 0;  // lines that ran from a's pixels into b's
  // With list_body_patches: the patches (other than a and b) of the own-blob front pixels, the
  // body in the gap; ascending, each once.
  std::vector<std::int32_t> body_patches;
};

// The plane through the middle of two planes' centroids with their mean normal: the surface two
// pieces of one plane lie on, and the chord plane of two pieces of one curved surface.
FittedPlane plane_between(const FittedPlane& a, const FittedPlane& b);

// Whether the gap holds enough occluding pixels: at least min_gap_px valid pixels, at least
// min_front_share of them in front, and at least one line that ran from a into b.
bool is_occluded(const GapEvidence& gap, std::int32_t min_gap_px, double min_front_share);

// The same with the pixels of a body of the patches' own blob counted as occluding, for a body
// that stands on the surface (partition.graph's coplanar_body_on_surface decides that).
bool is_occluded_by_own_body(const GapEvidence& gap, std::int32_t min_gap_px,
                             double min_front_share);

// Samples `lines` image lines from patch a to patch b: the one through both mean pixels and
// lines beside it, spread over the narrower patch's width across the line. On each line the gap
// is the stretch after the last pixel of a and before the first pixel of b; each gap pixel's 3D
// point is classified against `surface` (front: signed distance > front_margin_m) and by its
// blob. With list_body_patches, the patches of the front pixels of the two patches' own blobs
// are listed. Cost: the lines' lengths in pixels.
GapEvidence look_between(const GraphNode& a, const GraphNode& b, const FrameImages& images,
                         const FittedPlane& surface, double front_margin_m, std::int32_t lines,
                         bool list_body_patches = false);

}  // namespace facet::partition
