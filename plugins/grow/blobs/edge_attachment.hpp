#pragma once
// Edge pixels into blobs. The blobs of the patches are grown first, so that the bands of edge
// pixels between two objects (a box and the one stacked on it, two touching boxes) keep them
// apart as in the paper; then each edge pixel joins the blob it is connected to through other
// edge pixels (breadth first from the blobs, neighbours closer than the blob distance), and the
// edge pixels no blob reaches form blobs of their own: objects whose every pixel is an edge
// (a small ball, a cup's rim) that grew no patch.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <span>

#include "blobs/euclidean_regions.hpp"
#include "facet/algo/region_size_rule.hpp"

namespace facet::blobs {

struct EdgeAttachment {
  std::int64_t attached_px = 0;      // edge pixels that joined a blob of the patches
  std::int32_t edge_only_blobs = 0;  // blobs made of edge pixels alone
};

// blobs: the regions of the patch pixels, as grow_euclidean_regions returns them (updated in
// place; ids stay in raster order of each blob's first pixel). edges: CV_8UC1, non-zero = an edge
// pixel that may join (finite point, in no patch, on no plane); edge_pixels: the raster indices
// of those pixels, in raster order, so that the work follows the edge pixels, not the image.
// xyz: CV_32FC3, continuous. Neighbours link when the gate finds them close. New blobs that
// `own_blob_size` does not keep (by their pixel count and the depth of their first pixel) are
// left out; nullptr makes none (the edge pixels only join the blobs there are).
EdgeAttachment attach_edge_pixels(EuclideanRegions& blobs, const cv::Mat& edges,
                                  std::span<const std::int32_t> edge_pixels, const cv::Mat& xyz,
                                  const algo::NeighbourGate& gate,
                                  const algo::RegionSizeRule* own_blob_size);

}  // namespace facet::blobs
