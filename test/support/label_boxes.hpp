#pragma once
// Hand-made label images for the tests of stages that compare segments: rectangles of ids on a
// background of 0.

#include <cstdint>
#include <initializer_list>
#include <opencv2/core.hpp>

namespace facet::test {

struct LabelBox {
  std::int32_t id;
  cv::Rect rect;
};

// CV_32SC1 of `size`, 0 except for the boxes, drawn in order (a later box covers an earlier one).
inline cv::Mat label_boxes(cv::Size size, std::initializer_list<LabelBox> boxes) {
  cv::Mat labels = cv::Mat::zeros(size, CV_32SC1);
  for (const LabelBox& box : boxes)
    labels(box.rect).setTo(box.id);
  return labels;
}

}  // namespace facet::test
