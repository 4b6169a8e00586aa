#pragma once
// Angular deviation of surface normals between two frames of a static scene, pixel by pixel
// (the paper's Table I).

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace facet::eval {

// Degrees between the normals of the two CV_32FC3 images (same size) at every pixel where
// `region` (CV_8UC1, same size) is non-zero and both normals are valid (finite, non-zero); an
// empty region is the whole image. In row-major pixel order.
std::vector<double> angular_deviations_deg(const cv::Mat& normals_before,
                                           const cv::Mat& normals_after, const cv::Mat& region);

// "x, y, width, height" in pixels -> the rectangle; empty text -> an empty rectangle. Throws
// StageError naming `param` on anything else.
cv::Rect parse_roi(const std::string& text, const char* param);

}  // namespace facet::eval
