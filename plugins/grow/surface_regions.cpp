#include "grow/surface_regions.hpp"

#include <algorithm>
#include <stdexcept>

#include "grow/pixel_classes.hpp"

namespace facet::grow {

SurfaceRegions SurfaceRegionLabeler::label(const cv::Mat& classes, int connectivity,
                                           std::int64_t min_size_px) {
  if (classes.type() != CV_8UC1) throw std::invalid_argument("pixel classes must be CV_8UC1");
  if (connectivity != 4 && connectivity != 8) {
    throw std::invalid_argument("connectivity must be 4 or 8");
  }
  SurfaceRegions result;
  // The image lives inside a buffer with zero guard rows above and below (a whole row and
  // kLabelGuardPx more pixels, even in narrow images), so that the assignment pass can load the
  // labels around any pixel as whole vectors. A full-width row range is still a continuous image.
  const int width = classes.cols;
  const int guard_rows = 1 + (kLabelGuardPx + width - 1) / std::max(width, 1);
  cv::Mat buffer(classes.rows + 2 * guard_rows, width, CV_32SC1);
  buffer.rowRange(0, guard_rows).setTo(0);
  buffer.rowRange(guard_rows + classes.rows, buffer.rows).setTo(0);
  result.labels = buffer.rowRange(guard_rows, guard_rows + classes.rows);
  const algo::Components regions =
      components_.label(classes, kSurfacePixel, connectivity, min_size_px, result.labels);
  result.count = regions.count;
  result.labelled_px = regions.labelled_px;
  return result;
}

}  // namespace facet::grow
