#pragma once
// The nodes of the surface-patch graph (partition.graph): every usable (blob, patch) segment,
// with the geometry the edge features test, and one node per blob that has no usable patch.

#include <array>
#include <cstdint>
#include <vector>

#include "partition/blob_segments.hpp"
#include "partition/segment_plane.hpp"

namespace facet::partition {

struct NodeRule {
  std::int32_t min_patch_px = 100;  // smaller patches take part only as leftover pixels
  double planar_max_rms_m = 0.003;  // plane fit residual up to this: planar, above: curved
};

struct GraphNode {
  std::int32_t blob = 0;
  std::int32_t patch = 0;     // 0 for a blob without a usable patch
  std::int32_t segment = -1;  // index into BlobSegments::segments; -1 for a patchless blob
  FittedPlane plane;
  double plane_rms_m = 0.0;
  bool planar = false;
  Bounds bounds;  // 3D, metres
  // Where the patch is in the image: mean pixel and bounding box (inclusive), pixels.
  double centre_u_px = 0.0;
  double centre_v_px = 0.0;
  std::array<std::int32_t, 4> box_px{0, 0, 0, 0};  // u_min, v_min, u_max, v_max
  std::int32_t size_px = 0;
  std::int32_t first_pixel = 0;  // flat index of a pixel of the node (its first in raster order)
};

// Nodes in blob order, then ascending patch id (the order of BlobSegments): deterministic.
class GraphNodes {
 public:
  void build(const BlobSegments& points, int image_width, const NodeRule& rule);

  std::vector<GraphNode> nodes;
  // For each entry of BlobSegments::blobs, the node range [blob_begin, blob_end).
  std::vector<std::int32_t> blob_begin;
  std::vector<std::int32_t> blob_end;
};

// Shortest distance between two axis-aligned boxes (0 when they overlap), metres.
double box_gap_m(const Bounds& a, const Bounds& b);

}  // namespace facet::partition
