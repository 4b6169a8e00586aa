#pragma once
// Back-projection of a depth image through a pinhole camera (the kernel behind convert.points).

#include <opencv2/core/mat.hpp>

#include "facet/types/frame.hpp"

namespace facet::convert {

// Which depths count as measured, in metres. A bound of 0 is no bound.
struct DepthRange {
  double min_m = 0.0;
  double max_m = 0.0;
};

// Returns CV_32FC3 points in metres, X = (u - cx) Z / fx, Y = (v - cy) Z / fy, Z = depth.
// depth: CV_16UC1 millimetres (0 = invalid) or CV_32FC1 metres (0, negative or NaN = invalid).
// Invalid pixels and depths outside `range` become (NaN, NaN, NaN).
// Throws std::invalid_argument for another image type or invalid intrinsics.
cv::Mat back_project(const cv::Mat& depth, const CameraIntrinsics& camera, DepthRange range = {});

}  // namespace facet::convert
