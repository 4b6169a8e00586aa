#include "grow/edge_assignment.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "grow/pixel_classes.hpp"

namespace facet::grow {
namespace {

// Per pixel: the round in which it got its label (0 = a patch from region growing), or one of
// these markers.
constexpr std::uint8_t kUnassigned = 255;
constexpr std::uint8_t kQueued = 254;  // a candidate of the current round
constexpr std::uint8_t kInvalid = 253;

// The 8 neighbours in raster order, as (dx, dy).
constexpr int kNeighbourSteps[8][2] = {{-1, -1}, {0, -1}, {1, -1}, {-1, 0},
                                       {1, 0},   {-1, 1}, {0, 1},  {1, 1}};

class Propagation {
 public:
  Propagation(cv::Mat& labels, const cv::Mat& classes, const cv::Mat& points,
              const AssignmentRule& rule)
      : labels_(labels.ptr<std::int32_t>()),
        points_(points.ptr<float>()),
        width_(labels.cols),
        height_(labels.rows),
        gate_sq_m2_(static_cast<float>(rule.max_distance_m * rule.max_distance_m)),
        round_(labels.total()) {
    for (int n = 0; n < 8; ++n) {
      offsets_[static_cast<std::size_t>(n)] =
          static_cast<std::ptrdiff_t>(kNeighbourSteps[n][1]) * width_ + kNeighbourSteps[n][0];
    }
    for (int row = 0; row < height_; ++row) {
      const std::int32_t* label = labels.ptr<std::int32_t>(row);
      const unsigned char* pixel_class = classes.ptr<unsigned char>(row);
      std::uint8_t* out = round_.data() + index(row, 0);
      for (int x = 0; x < width_; ++x) {
        out[x] = label[x] != 0 ? 0 : (pixel_class[x] != kInvalidPixel ? kUnassigned : kInvalid);
      }
    }
  }

  // Round 1 visits every unassigned pixel; later rounds only the neighbours of the pixels the
  // previous round assigned.
  AssignmentResult run(int radius_px) {
    AssignmentResult result;
    std::vector<std::size_t> assigned;
    for (int row = 0; row < height_; ++row) {
      for (int col = 0; col < width_; ++col) {
        const std::size_t i = index(row, col);
        if (round_[i] != kUnassigned) continue;
        ++result.unassigned_px;
        if (radius_px >= 1 && try_assign(row, col, 1)) assigned.push_back(i);
      }
    }
    std::vector<std::size_t> candidates;
    for (int r = 2; r <= radius_px && !assigned.empty(); ++r) {
      result.assigned_px += static_cast<std::int64_t>(assigned.size());
      candidates.clear();
      for (const std::size_t i : assigned)
        queue_unassigned_neighbours(i, candidates);
      assigned.clear();
      for (const std::size_t i : candidates) {
        const int row = static_cast<int>(i / static_cast<std::size_t>(width_));
        const int col = static_cast<int>(i % static_cast<std::size_t>(width_));
        round_[i] = kUnassigned;  // unless assigned now; a later round may reach it again
        if (try_assign(row, col, r)) assigned.push_back(i);
      }
    }
    result.assigned_px += static_cast<std::int64_t>(assigned.size());
    result.unassigned_px -= result.assigned_px;
    return result;
  }

 private:
  std::size_t index(int row, int col) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(col);
  }

  // Takes the label of the 3D-closest neighbour labelled before round r, within the gate.
  bool try_assign(int row, int col, int r) {
    const std::size_t i = index(row, col);
    const bool interior = row > 0 && col > 0 && row + 1 < height_ && col + 1 < width_;
    // Cheap rejection first: most candidates of round 1 have no labelled neighbour at all.
    if (interior) {
      bool any = false;
      for (const std::ptrdiff_t offset : offsets_)
        any |= round_[i + offset] < r;
      if (!any) return false;
    }
    const float* p = points_ + 3 * i;
    float best_sq = gate_sq_m2_;
    std::int32_t best_label = 0;
    // Raster order, so that with strict < the first of equally close neighbours wins.
    for (int n = 0; n < 8; ++n) {
      const int y = row + kNeighbourSteps[n][1];
      const int x = col + kNeighbourSteps[n][0];
      if (!interior && (y < 0 || y >= height_ || x < 0 || x >= width_)) continue;
      const std::size_t q = index(y, x);
      if (round_[q] >= r) continue;  // unlabelled, or labelled in this round
      const float* pq = points_ + 3 * q;
      const float ex = pq[0] - p[0];
      const float ey = pq[1] - p[1];
      const float ez = pq[2] - p[2];
      const float distance_sq = ex * ex + ey * ey + ez * ez;
      if (distance_sq < best_sq) {  // false for NaN
        best_sq = distance_sq;
        best_label = labels_[q];
      }
    }
    if (best_label == 0) return false;
    labels_[i] = best_label;
    round_[i] = static_cast<std::uint8_t>(r);
    return true;
  }

  void queue_unassigned_neighbours(std::size_t i, std::vector<std::size_t>& candidates) {
    const int row = static_cast<int>(i / static_cast<std::size_t>(width_));
    const int col = static_cast<int>(i % static_cast<std::size_t>(width_));
    for (int y = std::max(row - 1, 0); y <= std::min(row + 1, height_ - 1); ++y) {
      for (int x = std::max(col - 1, 0); x <= std::min(col + 1, width_ - 1); ++x) {
        const std::size_t q = index(y, x);
        if (round_[q] != kUnassigned) continue;
        round_[q] = kQueued;
        candidates.push_back(q);
      }
    }
  }

  std::int32_t* labels_;
  const float* points_;
  int width_;
  int height_;
  float gate_sq_m2_;
  std::vector<std::uint8_t> round_;
  std::array<std::ptrdiff_t, 8> offsets_{};  // the 8 neighbours as index offsets
};

}  // namespace

AssignmentResult assign_to_nearest_patch(cv::Mat& labels, const cv::Mat& classes,
                                         const cv::Mat& points, const AssignmentRule& rule) {
  if (labels.type() != CV_32SC1 || classes.type() != CV_8UC1 || points.type() != CV_32FC3 ||
      labels.size() != points.size() || classes.size() != labels.size()) {
    throw std::invalid_argument(
        "labels (CV_32SC1), classes (CV_8UC1) and points (CV_32FC3) must have one size");
  }
  if (!labels.isContinuous() || !points.isContinuous()) {
    throw std::invalid_argument("labels and points must be continuous images");
  }
  if (rule.radius_px > 250) throw std::invalid_argument("assignment radius above 250 px");
  Propagation propagation(labels, classes, points, rule);
  return propagation.run(rule.radius_px);
}

}  // namespace facet::grow
