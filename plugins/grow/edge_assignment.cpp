#include "grow/edge_assignment.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <stdexcept>

#include "grow/assignment_rows.hpp"
#include "grow/neighbour_steps.hpp"

namespace facet::grow {

EdgeAssignment::EdgeAssignment(const AssignmentRule& rule)
    : rule_(rule), gate_sq_m2_(static_cast<float>(rule.max_distance_m * rule.max_distance_m)) {
  if (rule.radius_px < 0 || rule.radius_px > 250) {
    throw std::invalid_argument("assignment radius outside 0..250 px");
  }
}

// The rounds run as a wavefront down the image: at step t, round 1 runs on row t, round 2 on
// row t - 1, ..., round r on row t - r + 1, in that order. When round r runs on row y, rounds
// up to r - 1 are complete on rows y - 1..y + 1 (row y + 1 had round r - 1 just before, in this
// step) and no later round has touched them (round r + 1 on row y - 1 follows in this step), so
// every pixel sees exactly the labels of the earlier rounds, as with one image-wide pass per
// round. The gain is locality: all rounds read the same few rows of points and labels while
// they are still in cache, instead of sweeping the 3.7 MB point image once per round.
AssignmentResult EdgeAssignment::assign(cv::Mat& labels, const cv::Mat& classes,
                                        const cv::Mat& points) {
  if (labels.type() != CV_32SC1 || classes.type() != CV_8UC1 || points.type() != CV_32FC3 ||
      labels.size() != points.size() || classes.size() != labels.size()) {
    throw std::invalid_argument(
        "labels (CV_32SC1), classes (CV_8UC1) and points (CV_32FC3) must have one size");
  }
  if (!labels.isContinuous() || !points.isContinuous()) {
    throw std::invalid_argument("labels and points must be continuous images");
  }
  AssignmentResult result;
  result.unassigned_px = build_state(labels, classes);
  const int rounds = rule_.radius_px;
  if (rounds == 0 || labels.empty()) return result;

  const auto guarded_rows = static_cast<std::size_t>(height_ + 2);
  assigned_px_.assign(static_cast<std::size_t>(rounds + 1) * guarded_rows, 0);
  std::fill_n(assigned_px_.begin() + 1, height_, 1);
  // Row buffer, with room for the kernels' last 8-pixel word (zero: no candidate there).
  candidates_.assign(static_cast<std::size_t>(width_) + 8, 0);
  // Round r on row y reads the points of rows y - 1..y + 1, so the wavefront works on rows
  // step - rounds..step + 1.
  const float* point_data = points.ptr<float>();
  point_rows_.reset(width_, height_, std::min(rounds + 2, height_ + 2), kInvalidState);
  point_rows_.load(-1, point_data, nullptr);
  point_rows_.load(0, point_data, state_row(0));

  auto* label_data = labels.ptr<std::int32_t>();
  for (int step = 0; step < height_ + rounds - 1; ++step) {
    point_rows_.load(step + 1, point_data, step + 1 < height_ ? state_row(step + 1) : nullptr);
    for (int round = 1; round <= rounds && step - round + 1 >= 0; ++round) {
      const int row = step - round + 1;
      if (row >= height_ || !row_may_change(row, round)) continue;
      const int assigned = run_round_on_row(label_data, row, static_cast<std::uint8_t>(round));
      assigned_px_[static_cast<std::size_t>(round) * guarded_rows +
                   static_cast<std::size_t>(row + 1)] = assigned;
      result.assigned_px += assigned;
    }
  }
  result.unassigned_px -= result.assigned_px;
  return result;
}

// Returns the number of unassigned valid pixels.
std::int64_t EdgeAssignment::build_state(const cv::Mat& labels, const cv::Mat& classes) {
  width_ = labels.cols;
  height_ = labels.rows;
  state_stride_ = width_ + 2;
  // + 8: the kernels' vector loads of the last guard row may run past its end.
  state_.assign(static_cast<std::size_t>(state_stride_) * static_cast<std::size_t>(height_ + 2) + 8,
                kInvalidState);
  std::int64_t unassigned_px = 0;
  for (int row = 0; row < height_; ++row) {
    unassigned_px += fill_state_row(labels.ptr<std::int32_t>(row), classes.ptr<std::uint8_t>(row),
                                    state_.data() + (row + 1) * state_stride_ + 1, width_);
  }
  return unassigned_px;
}

// Only pixels next to one labelled in the previous round can change in this round: a pixel
// whose labelled neighbours are all older already failed the gate against each of them.
bool EdgeAssignment::row_may_change(int row, int round) const {
  const auto* previous =
      assigned_px_.data() +
      static_cast<std::size_t>(round - 1) * static_cast<std::size_t>(height_ + 2) +
      static_cast<std::size_t>(row + 1);
  return (previous[-1] | previous[0] | previous[1]) != 0;
}

// One round on one row: a byte mask marks the unassigned pixels with a neighbour labelled in
// the previous round, without branching (most of a row is inside a patch, invalid, or deep in
// an edge band); the nearest neighbour is chosen, vectorised, only in 8-pixel words holding a
// candidate. Returns how many pixels took a label.
int EdgeAssignment::run_round_on_row(std::int32_t* labels, int row, std::uint8_t round) {
  std::uint8_t* state = state_row(row);
  std::uint8_t* candidate = candidates_.data();
  find_round_candidates(state - state_stride_, state, state + state_stride_,
                        static_cast<std::uint8_t>(round - 1), candidate, width_);
  NeighbourRows rows{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      rows.coordinates[r][c] = point_rows_.coordinates(row + r - 1, c);
    rows.state[r] = point_rows_.state(row + r - 1);
    // Rows -1 and height are the guard rows of the label buffer (kLabelGuardPx).
    rows.labels[r] = labels + static_cast<std::ptrdiff_t>(row + r - 1) * width_;
  }
  std::int32_t* label_row = labels + static_cast<std::ptrdiff_t>(row) * width_;
  return assign_nearest_neighbours(rows, candidate, round, gate_sq_m2_, label_row, state,
                                   point_rows_.state(row), width_);
}

}  // namespace facet::grow
