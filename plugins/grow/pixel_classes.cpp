#include "grow/pixel_classes.hpp"

namespace facet::grow {

cv::Mat classify_pixels(const cv::Mat& edge_mask, const cv::Mat& points) {
  cv::Mat classes(edge_mask.size(), CV_8UC1);
  for (int row = 0; row < edge_mask.rows; ++row) {
    const unsigned char* __restrict edge = edge_mask.ptr<unsigned char>(row);
    const float* __restrict xyz = points.ptr<float>(row);
    unsigned char* __restrict out = classes.ptr<unsigned char>(row);
    for (int x = 0; x < edge_mask.cols; ++x) {
      // A NaN z compares false: invalid.
      const bool valid = xyz[3 * x + 2] > 0.0F;
      out[x] = valid ? (edge[x] != 0 ? kEdgePixel : kSurfacePixel) : kInvalidPixel;
    }
  }
  return classes;
}

}  // namespace facet::grow
