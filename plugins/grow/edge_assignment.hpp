#pragma once
// The one assignment pass after region growing: edge pixels (and pixels of regions too small to
// keep) join the nearest surface patch, stepping only between pixels that are close in 3D.

#include <cstdint>
#include <opencv2/core/mat.hpp>

namespace facet::grow {

struct AssignmentRule {
  int radius_px = 5;             // rho: at most this many steps from the patch
  double max_distance_m = 0.01;  // every step must be shorter than this in 3D
};

struct AssignmentResult {
  std::int64_t assigned_px = 0;    // pixels that received a label in this pass
  std::int64_t unassigned_px = 0;  // valid pixels left at 0
};

// labels: CV_32SC1 patch ids, 0 = unassigned; updated in place. classes: CV_8UC1 PixelClass
// (only valid pixels are assigned). points: CV_32FC3 in metres.
//
// Breadth-first propagation in rounds r = 1..radius_px: in round r, every unassigned valid pixel
// that has an 8-neighbour labelled before round r takes the label of the neighbour closest to
// it in 3D among those closer than max_distance_m (ties: the first in raster order). So a pixel
// joins the patch it is fewest steps from, every step follows the surface, a depth step larger
// than the gate is never crossed, and the source pixel lies within the (2 rho + 1)^2 window.
// A round reads only labels from earlier rounds, so the result does not depend on scan order.
AssignmentResult assign_to_nearest_patch(cv::Mat& labels, const cv::Mat& classes,
                                         const cv::Mat& points, const AssignmentRule& rule);

}  // namespace facet::grow
