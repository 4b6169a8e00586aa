#pragma once
// The one assignment pass after region growing: edge pixels (and pixels of regions too small to
// keep) join the nearest surface patch, stepping only between pixels that are close in 3D.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "grow/point_rows.hpp"

namespace facet::grow {

struct AssignmentRule {
  int radius_px = 5;             // rho: at most this many steps from the patch
  double max_distance_m = 0.01;  // every step must be shorter than this in 3D
};

struct AssignmentResult {
  std::int64_t assigned_px = 0;    // pixels that received a label in this pass
  std::int64_t unassigned_px = 0;  // valid pixels left at 0
};

// Breadth-first propagation in rounds r = 1..radius_px: in round r, every unassigned valid pixel
// that has an 8-neighbour labelled before round r takes the label of the neighbour closest to
// it in 3D among those closer than max_distance_m (ties: the first in raster order). So a pixel
// joins the patch it is fewest steps from, every step follows the surface, a depth step larger
// than the gate is never crossed, and the source pixel lies within the (2 rho + 1)^2 window.
// A round reads only labels from earlier rounds, so the result does not depend on scan order.
//
// Keeps its working memory between frames, so one instance serves one thread.
class EdgeAssignment {
 public:
  explicit EdgeAssignment(const AssignmentRule& rule);

  // labels: CV_32SC1 patch ids, 0 = unassigned; updated in place; readable for a row and
  // kLabelGuardPx pixels before and after the image, as SurfaceRegionLabeler makes it. classes:
  // CV_8UC1 PixelClass (only valid pixels are assigned). points: CV_32FC3 in metres. labels and
  // points continuous.
  AssignmentResult assign(cv::Mat& labels, const cv::Mat& classes, const cv::Mat& points);

 private:
  std::int64_t build_state(const cv::Mat& labels, const cv::Mat& classes);
  int run_round_on_row(std::int32_t* labels, int row, std::uint8_t round);
  bool row_may_change(int row, int round) const;
  std::uint8_t* state_row(int row) { return state_.data() + (row + 1) * state_stride_ + 1; }

  AssignmentRule rule_;
  float gate_sq_m2_;
  int width_ = 0;
  int height_ = 0;
  std::ptrdiff_t state_stride_ = 0;  // width + 2: one guard column on each side
  // Per pixel, with a one-pixel guard frame of kInvalidState: the round in which the pixel got
  // its label (0 = a patch from region growing), or kUnassignedState / kInvalidState.
  std::vector<std::uint8_t> state_;
  std::vector<std::uint8_t> candidates_;  // of one row in one round, as bytes 0/1
  PointRowRing point_rows_;               // the rows the wavefront is working on
  // assigned_px_[r * (height + 2) + row + 1]: pixels of a row labelled in round r (a guard row
  // above and below); round 0 marks every row as holding patch pixels.
  std::vector<int> assigned_px_;
};

}  // namespace facet::grow
