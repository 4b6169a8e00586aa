#pragma once
// The 3D points of each labelled object, gathered in one pass over the label and point images.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace facet::shape {

struct ObjectPoints {
  std::int32_t id = 0;
  std::int64_t pixel_count = 0;         // labelled pixels, valid point or not
  std::vector<Eigen::Vector3d> points;  // valid (finite) points only, metres, camera frame
};

// One entry per id that labels at least one pixel, in increasing id order. `labels` is CV_32SC1
// (0 = background), `points` CV_32FC3 of the same size; throws facet::StageError otherwise.
std::vector<ObjectPoints> gather_object_points(const cv::Mat& labels, const cv::Mat& points);

}  // namespace facet::shape
