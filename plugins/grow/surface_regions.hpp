#pragma once
// Connected regions of surface pixels (facet::algo's component labelling), in a label image with
// guard pixels around it for the assignment pass's vector loads.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/connected_components.hpp"
#include "facet/algo/region_size_rule.hpp"

namespace facet::grow {

// The label image of SurfaceRegions may be read (not written) up to this many pixels before its
// first and after its last pixel; those read 0.
constexpr int kLabelGuardPx = 16;

struct SurfaceRegions {
  // CV_32SC1: 1..count, 0 = not surface or in a region below the minimum size. Continuous, with
  // kLabelGuardPx readable guard pixels on either side.
  cv::Mat labels;
  std::int32_t count = 0;
  std::int64_t labelled_px = 0;  // pixels carrying a label
};

// Keeps its working memory between frames, so one instance serves one thread.
class SurfaceRegionLabeler {
 public:
  // classes: CV_8UC1 PixelClass; kSurfacePixel pixels are grown. connectivity: 4 or 8. points:
  // CV_32FC3 of the same size, in metres (its z is read only for the rule's depth; every surface
  // pixel has a valid point). Regions `size` does not keep are left at 0. Ids follow the raster
  // order (row, then column) of each region's first pixel, so the result does not depend on
  // anything but the input.
  SurfaceRegions label(const cv::Mat& classes, const cv::Mat& points, int connectivity,
                       const algo::RegionSizeRule& size);

 private:
  // Sets the regions under size.min_px that their depth does not excuse to 0 and renumbers the
  // rest, keeping their order.
  void drop_small_near_regions(const cv::Mat& points, const algo::RegionSizeRule& size,
                               SurfaceRegions& regions);

  algo::ComponentLabeler components_;
  std::vector<double> depth_sum_m_;  // per region under min_px, else unused
  std::vector<std::int32_t> new_id_;
};

}  // namespace facet::grow
