#include "partition/graph_nodes.hpp"

#include <algorithm>
#include <cmath>

namespace facet::partition {

void GraphNodes::build(const BlobSegments& points, int image_width, const NodeRule& rule) {
  nodes.clear();
  blob_begin.clear();
  blob_end.clear();
  for (const BlobRange& blob : points.blobs) {
    blob_begin.push_back(static_cast<std::int32_t>(nodes.size()));
    for (std::int32_t s = blob.segment_begin; s < blob.segment_end; ++s) {
      const Segment& segment = points.segments[static_cast<std::size_t>(s)];
      if (segment.patch == 0 || segment.size() < rule.min_patch_px) continue;
      GraphNode node;
      node.blob = blob.blob;
      node.patch = segment.patch;
      node.segment = s;
      node.plane = fit_plane(points, segment.begin, segment.end);
      // A patch whose points are collinear (or NaN-free but degenerate) has no plane to test
      // against; it joins an object as leftover pixels.
      if (!node.plane.valid) continue;
      node.plane_rms_m = plane_rms_m(points, node.plane, segment.begin, segment.end);
      node.planar = node.plane_rms_m <= rule.planar_max_rms_m;
      node.bounds = bounds_of(points, segment.begin, segment.end);
      double sum_u = 0.0;
      double sum_v = 0.0;
      std::array<std::int32_t, 4> box{image_width, 1 << 30, -1, -1};
      for (std::int32_t k = segment.begin; k < segment.end; ++k) {
        const std::int32_t i = points.pixel[static_cast<std::size_t>(k)];
        const std::int32_t u = i % image_width;
        const std::int32_t v = i / image_width;
        sum_u += u;
        sum_v += v;
        box = {std::min(box[0], u), std::min(box[1], v), std::max(box[2], u), std::max(box[3], v)};
      }
      node.size_px = segment.size();
      node.centre_u_px = sum_u / segment.size();
      node.centre_v_px = sum_v / segment.size();
      node.box_px = box;
      node.first_pixel = points.pixel[static_cast<std::size_t>(segment.begin)];
      nodes.push_back(node);
    }
    if (static_cast<std::int32_t>(nodes.size()) == blob_begin.back()) {
      // Nothing to partition by: the blob is one node, and one object unless nothing else
      // joins it (no feature can, it has no geometry to test).
      GraphNode node;
      node.blob = blob.blob;
      node.size_px = blob.end - blob.begin;
      node.first_pixel = points.pixel[static_cast<std::size_t>(blob.begin)];
      nodes.push_back(node);
    }
    blob_end.push_back(static_cast<std::int32_t>(nodes.size()));
  }
}

double box_gap_m(const Bounds& a, const Bounds& b) {
  if (a.empty || b.empty) return 0.0;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double gap = std::max({0.0,
                                 static_cast<double>(a.min_m[static_cast<std::size_t>(k)] -
                                                     b.max_m[static_cast<std::size_t>(k)]),
                                 static_cast<double>(b.min_m[static_cast<std::size_t>(k)] -
                                                     a.max_m[static_cast<std::size_t>(k)])});
    sum += gap * gap;
  }
  return std::sqrt(sum);
}

}  // namespace facet::partition
