#pragma once
// What region growing needs to know about each pixel, computed once from the edge mask and the
// points: one byte per pixel, read by the flood fill and by the assignment pass.

#include <cstdint>
#include <opencv2/core/mat.hpp>

namespace facet::grow {

enum PixelClass : std::uint8_t {
  kInvalidPixel = 0,  // no 3D point (z NaN or not positive): never labelled
  kEdgePixel = 1,     // valid point on an edge: may be assigned to a patch
  kSurfacePixel = 2,  // valid point, not an edge: grows into patches
};

// edge_mask: CV_8UC1 (non-zero = edge); points: CV_32FC3 of the same size. Returns CV_8UC1.
cv::Mat classify_pixels(const cv::Mat& edge_mask, const cv::Mat& points);

}  // namespace facet::grow
