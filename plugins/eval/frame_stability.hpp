#pragma once
// Frame-to-frame stability of a segmentation of a static scene (the paper's Table II): the
// segments of two consecutive frames are put in correspondence one to one by overlap, then
// how much corresponding segments overlap, how far their centroids moved, and which segments
// of the newer frame have no counterpart (spurious) or which of the older one vanished.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "eval/segment_matching.hpp"

namespace facet::eval {

struct StabilityOptions {
  OverlapMeasure measure = OverlapMeasure::mean_ratio;
  // Corresponding segments must overlap by more than this (0: any shared pixel).
  double min_overlap = 0.0;
};

struct FrameStability {
  std::int64_t segments = 0;        // in the newer frame
  std::int64_t spurious = 0;        // segments of the newer frame without a counterpart
  std::int64_t vanished = 0;        // segments of the older frame without a counterpart
  std::vector<double> overlaps;     // of every corresponding pair, 0..1
  std::vector<double> centroid_px;  // distance of the pixel centroids of every pair
  std::vector<double> centroid_mm;  // of the 3D centroids, pairs with valid points on both
};

// `labels_*`: CV_32SC1 segment ids (0 = none) of the same size; `points_*`: CV_32FC3 metres of
// that size (NaN = invalid), or empty for no 3D centroids.
FrameStability compare_frames(const cv::Mat& labels_before, const cv::Mat& points_before,
                              const cv::Mat& labels_after, const cv::Mat& points_after,
                              const StabilityOptions& options = {});

}  // namespace facet::eval
