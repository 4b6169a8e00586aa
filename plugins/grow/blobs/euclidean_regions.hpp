#pragma once
// Euclidean region growing on the image grid (paper sec. II-B e): 8-connected single linkage,
// two neighbouring pixels join when their 3D points are closer than a distance.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/neighbour_gate.hpp"
#include "facet/algo/region_size_rule.hpp"

namespace facet::blobs {

struct EuclideanRegions {
  cv::Mat labels;  // CV_32SC1, 1..count in raster order of each region's first pixel; 0 = none
  std::int32_t count = 0;
  // Raster index of each region's first pixel, by id (entry 0 unused), as the growing and the
  // edge attachment leave them; the steps that drop blobs do not keep it.
  std::vector<std::int64_t> first_px;
};

// mask: CV_8UC1, non-zero = pixel takes part (it must have a finite point). xyz: CV_32FC3,
// continuous, same size. Neighbours join when the gate finds them close. Regions `size` does
// not keep (by their pixel count and the depth of their first pixel) are left at 0.
EuclideanRegions grow_euclidean_regions(const cv::Mat& mask, const cv::Mat& xyz,
                                        const algo::NeighbourGate& gate,
                                        const algo::RegionSizeRule& size);

}  // namespace facet::blobs
