#pragma once
// Connected regions of surface pixels (facet::algo's component labelling), in a label image with
// guard pixels around it for the assignment pass's vector loads.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/connected_components.hpp"

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
  // classes: CV_8UC1 PixelClass; kSurfacePixel pixels are grown. connectivity: 4 or 8. Regions
  // smaller than min_size_px are left at 0. Ids follow the raster order (row, then column) of
  // each region's first pixel, so the result does not depend on anything but the input.
  SurfaceRegions label(const cv::Mat& classes, int connectivity, std::int64_t min_size_px);

 private:
  algo::ComponentLabeler components_;
};

}  // namespace facet::grow
