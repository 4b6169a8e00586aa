#pragma once
// Bodies without a patch of their own (partition.graph). Far from the camera a small body (a cup
// on a tray, the top box of a stack, a can behind a box) can lose every patch to its edge bands;
// its pixels would then be shared out to the object beside it, a merge. A wide unclaimed region
// is a body, not an edge band: it becomes an object of its own.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>
#include <vector>

#include "facet/algo/connected_components.hpp"
#include "partition/segment_plane.hpp"

namespace facet::partition {

struct CoreRule {
  double radius_px = 0.0;           // 0 = off
  double radius_m = 0.0;            // the inscribed radius must also reach this in 3D
  std::int32_t min_px = 20;         // smallest core
  double plane_tolerance_m = 0.01;  // a core this close to a touching face's plane is that face
};

// The planar faces the graph found: the node of each claimed pixel (CV_32SC1, -1 = none) and
// each node's plane (invalid for a curved node).
struct ClaimedFaces {
  const cv::Mat* node_of_pixel = nullptr;
  const std::vector<FittedPlane>* planes = nullptr;
};

// Images the search reuses from frame to frame (one per stage instance).
struct CoreBuffers {
  cv::Mat in_blob;
  cv::Mat unclaimed;
  cv::Mat framed;
  cv::Mat distance_px;
  cv::Mat wide_enough;
  cv::Mat core;
  cv::Mat region;
  algo::ComponentLabeler components;
};

// `objects` (CV_32SC1, continuous) holds the ids the graph gave. The blob pixels it left at 0
// that lie at least `radius_px` (Euclidean) from every other pixel form cores (connected, 8
// neighbours). A core of at least `min_px` pixels whose widest point is also at least `radius_m`
// from the region's border in 3D (pixels × depth / fx at that point) becomes an object of its own,
// ids from `next_id` on; fill_blob_gaps then shares the rest out to cores and objects alike. An
// edge band between two faces is about 5 px wide on each side whatever the distance, so it has no
// core; the metric radius keeps a near face that holes kept from becoming a patch (wide in pixels,
// narrow in metres) with its body. A core whose points lie mostly (half or more) within
// `plane_tolerance_m` of the plane of a planar face touching its region is the rest of that face
// (noise kept it from the patch) and stays with it too. Returns the next free id.
std::int32_t claim_unclaimed_cores(cv::Mat& objects, const cv::Mat& blobs, const cv::Mat& points,
                                   double fx_px, const ClaimedFaces& faces, const CoreRule& rule,
                                   CoreBuffers& buffers, std::int32_t next_id);

}  // namespace facet::partition
