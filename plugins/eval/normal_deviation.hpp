#pragma once
// Angular deviation of surface normals between two frames of a static scene, pixel by pixel
// (the paper's Table I).

#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "facet/contract.hpp"

namespace facet::eval {

// Degrees between the normals of the two CV_32FC3 images (same size) at every pixel where
// `region` (CV_8UC1, same size) is non-zero and both normals are valid (finite, non-zero); an
// empty region is the whole image. In row-major pixel order.
std::vector<double> angular_deviations_deg(const cv::Mat& normals_before,
                                           const cv::Mat& normals_after, const cv::Mat& region);

// A region of the image, written "x, y, width, height" in pixels (empty = none, an empty
// rectangle): eval.normal_stability's roi.
struct PixelRect {
  cv::Rect rect;
};

}  // namespace facet::eval

template <>
struct facet::ParamTraits<facet::eval::PixelRect> {
  static std::variant<facet::eval::PixelRect, std::string> parse(std::string_view text);
  static std::string format(const facet::eval::PixelRect& value);
};
