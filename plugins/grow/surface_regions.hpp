#pragma once
// Connected regions of surface pixels, labelled through runs of pixels rather than pixel by
// pixel: a region of a depth image is a few hundred runs, not tens of thousands of pixels.

#include <cstdint>
#include <opencv2/core/mat.hpp>

namespace facet::grow {

struct SurfaceRegions {
  cv::Mat labels;  // CV_32SC1: 1..count, 0 = not surface or in a region below the minimum size
  std::int32_t count = 0;
  std::int64_t labelled_px = 0;  // pixels carrying a label
};

// classes: CV_8UC1 PixelClass; kSurfacePixel pixels are grown. connectivity: 4 or 8. Regions
// smaller than min_size_px are left at 0. Ids follow the raster order (row, then column) of each
// region's first pixel, so the result does not depend on anything but the input.
SurfaceRegions label_surface_regions(const cv::Mat& classes, int connectivity,
                                     std::int64_t min_size_px);

}  // namespace facet::grow
