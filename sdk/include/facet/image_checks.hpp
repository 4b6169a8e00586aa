#pragma once
// Checks of a stage's input images, with errors that name the port and what was found.

#include <opencv2/core/mat.hpp>
#include <string_view>

namespace facet {

// Throws StageError "input 'points' must be CV_32FC3, got CV_16UC1" when `image` has another type.
void require_type(const cv::Mat& image, int type, std::string_view port);

// Throws StageError "inputs 'patches' (640x480) and 'points' (320x240) differ in size".
void require_same_size(const cv::Mat& a, std::string_view port_a, const cv::Mat& b,
                       std::string_view port_b);

}  // namespace facet
