#include "eval/overlap_scores.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "eval/assignment.hpp"

namespace facet::eval {
namespace {

cv::Mat as_int32(const cv::Mat& labels, const char* what) {
  if (labels.channels() != 1 ||
      (labels.depth() != CV_8U && labels.depth() != CV_16U && labels.depth() != CV_32S)) {
    throw std::invalid_argument(std::string(what) +
                                ": expected a single-channel 8-, 16- or 32-bit label image");
  }
  if (labels.type() == CV_32SC1) return labels;
  cv::Mat converted;
  labels.convertTo(converted, CV_32S);
  return converted;
}

// Dense indices 0..n-1 for the ids met, in order of first appearance.
class IdIndex {
 public:
  std::size_t index_of(std::int32_t id) {
    const auto [it, inserted] = index_.try_emplace(id, pixels_.size());
    if (inserted) pixels_.push_back(0);
    return it->second;
  }
  std::size_t size() const { return pixels_.size(); }
  std::int64_t& pixels(std::size_t index) { return pixels_[index]; }
  std::int64_t pixels(std::size_t index) const { return pixels_[index]; }

 private:
  std::unordered_map<std::int32_t, std::size_t> index_;
  std::vector<std::int64_t> pixels_;
};

// Truth ids after background ids and small objects are taken out: 0 = background, -1 = pixel
// ignored in both images.
cv::Mat effective_truth(const cv::Mat& truth, const OverlapOptions& options) {
  cv::Mat effective = truth.clone();
  std::unordered_map<std::int32_t, std::int64_t> counts;
  for (int y = 0; y < effective.rows; ++y) {
    auto* row = effective.ptr<std::int32_t>(y);
    for (int x = 0; x < effective.cols; ++x) {
      if (row[x] != 0 && options.truth_background.count(row[x]) > 0) row[x] = 0;
      if (row[x] != 0) ++counts[row[x]];
    }
  }
  if (options.min_truth_pixels <= 0) return effective;
  for (int y = 0; y < effective.rows; ++y) {
    auto* row = effective.ptr<std::int32_t>(y);
    for (int x = 0; x < effective.cols; ++x) {
      if (row[x] != 0 && counts[row[x]] < options.min_truth_pixels) row[x] = -1;
    }
  }
  return effective;
}

double pair_f(std::int64_t overlap, std::int64_t truth, std::int64_t segment) {
  return truth + segment > 0
             ? 2.0 * static_cast<double>(overlap) / static_cast<double>(truth + segment)
             : 0.0;
}

}  // namespace

OverlapScores score_overlap(const cv::Mat& truth_image, const cv::Mat& predicted_image,
                            const OverlapOptions& options) {
  if (truth_image.size() != predicted_image.size()) {
    throw std::invalid_argument(
        "truth is " + std::to_string(truth_image.cols) + "x" + std::to_string(truth_image.rows) +
        ", prediction " + std::to_string(predicted_image.cols) + "x" +
        std::to_string(predicted_image.rows) + ": the label images must have the same size");
  }
  const cv::Mat truth = effective_truth(as_int32(truth_image, "truth"), options);
  const cv::Mat predicted = as_int32(predicted_image, "prediction");

  // One pass: object and segment sizes, and the overlap of every (object, segment) pair.
  IdIndex objects;
  IdIndex segments;
  std::unordered_map<std::uint64_t, std::int64_t> overlaps;  // object index << 32 | segment index
  for (int y = 0; y < truth.rows; ++y) {
    const auto* truth_row = truth.ptr<std::int32_t>(y);
    const auto* predicted_row = predicted.ptr<std::int32_t>(y);
    for (int x = 0; x < truth.cols; ++x) {
      const std::int32_t t = truth_row[x];
      const std::int32_t p = predicted_row[x];
      if (t < 0) continue;
      std::size_t object = 0;
      std::size_t segment = 0;
      if (t != 0) {
        object = objects.index_of(t);
        ++objects.pixels(object);
      }
      if (p != 0) {
        segment = segments.index_of(p);
        ++segments.pixels(segment);
      }
      if (t != 0 && p != 0) ++overlaps[(static_cast<std::uint64_t>(object) << 32) | segment];
    }
  }

  OverlapScores scores;
  const std::size_t n = objects.size();
  const std::size_t m = segments.size();
  scores.truth_objects = static_cast<std::int64_t>(n);
  scores.segments = static_cast<std::int64_t>(m);
  if (n == 0 || m == 0) {
    // As UOIS: nothing on either side is perfect; one side empty scores F = 0.
    scores.precision = (n == 0 && m > 0) ? 0.0 : 1.0;
    scores.recall = (m == 0 && n > 0) ? 0.0 : 1.0;
    scores.f = (n == 0 && m == 0) ? 1.0 : 0.0;
    return scores;
  }

  std::vector<std::int64_t> overlap(n * m, 0);
  for (const auto& [key, pixels] : overlaps) {
    overlap[(key >> 32) * m + (key & 0xffffffffU)] = pixels;
  }
  WeightMatrix iou(n, m);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      const std::int64_t both = overlap[i * m + j];
      const std::int64_t either = objects.pixels(i) + segments.pixels(j) - both;
      iou.at(i, j) = static_cast<double>(both) / static_cast<double>(either);
    }
  }
  const auto match = max_weight_assignment(iou);

  std::int64_t matched_pixels = 0;
  std::int64_t truth_pixels = 0;
  std::int64_t segment_pixels = 0;
  for (std::size_t i = 0; i < n; ++i)
    truth_pixels += objects.pixels(i);
  for (std::size_t j = 0; j < m; ++j)
    segment_pixels += segments.pixels(j);
  double iou_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!match[i]) continue;
    const std::size_t j = *match[i];
    const std::int64_t both = overlap[i * m + j];
    if (both == 0) continue;  // an assigned pair without overlap is no match
    ++scores.matched;
    matched_pixels += both;
    iou_sum += iou.at(i, j);
    if (pair_f(both, objects.pixels(i), segments.pixels(j)) >= options.segmented_f) {
      ++scores.objects_segmented;
    }
  }
  scores.precision = static_cast<double>(matched_pixels) / static_cast<double>(segment_pixels);
  scores.recall = static_cast<double>(matched_pixels) / static_cast<double>(truth_pixels);
  const double sum = scores.precision + scores.recall;
  scores.f = sum > 0.0 ? 2.0 * scores.precision * scores.recall / sum : 0.0;
  scores.objects_segmented_ratio =
      static_cast<double>(scores.objects_segmented) / static_cast<double>(n);
  scores.mean_iou = iou_sum / static_cast<double>(n);

  // Coverage: segment j holds at least `cover` of object i's pixels.
  const auto covers = [&](std::size_t i, std::size_t j) {
    return static_cast<double>(overlap[i * m + j]) >=
               options.cover * static_cast<double>(objects.pixels(i)) &&
           overlap[i * m + j] > 0;
  };
  std::vector<bool> under(m, false);
  for (std::size_t j = 0; j < m; ++j) {
    int covered = 0;
    for (std::size_t i = 0; i < n; ++i)
      covered += covers(i, j) ? 1 : 0;
    under[j] = covered >= 2;
    if (under[j]) ++scores.under_segmenting;
  }
  for (std::size_t i = 0; i < n; ++i) {
    int covering = 0;
    bool merged = false;
    for (std::size_t j = 0; j < m; ++j) {
      if (!covers(i, j)) continue;
      ++covering;
      merged = merged || under[j];
    }
    if (covering >= 2) ++scores.over_segmented;
    if (merged) ++scores.merged_objects;
  }
  return scores;
}

}  // namespace facet::eval
