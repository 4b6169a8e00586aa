#pragma once
// Checks across a stage's input images, with errors that name the ports and what was found. (Each
// image's own format is checked by its type: facet/types/images.hpp.)

#include <opencv2/core/mat.hpp>
#include <string_view>

namespace facet {

// Throws StageError "inputs 'patches' (640x480) and 'points' (320x240) differ in size".
void require_same_size(const cv::Mat& a, std::string_view port_a, const cv::Mat& b,
                       std::string_view port_b);

}  // namespace facet
