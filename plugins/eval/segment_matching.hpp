#pragma once
// One-to-one correspondence of the segments of two label images (two frames of a video, or a
// frame and the tracks remembered from earlier ones) by their pixel overlap, with the Hungarian
// method of assignment.hpp. Shared by eval.stability and track.labels.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace facet::eval {

// How much two segments i and j overlap, from |i|, |j| and |i ∩ j|.
enum class OverlapMeasure {
  mean_ratio,  // ½ (|i∩j|/|i| + |i∩j|/|j|): the authors' later code; 1 for identical segments
  iou,         // |i∩j| / |i ∪ j|: the external scorer's stability mode
};

double overlap_of(OverlapMeasure measure, std::int64_t both, std::int64_t pixels_a,
                  std::int64_t pixels_b);

// Sizes of the segments on side a and b and the pixels each pair shares (a-major).
struct OverlapTable {
  std::vector<std::int32_t> ids_a;  // ascending
  std::vector<std::int32_t> ids_b;  // ascending
  std::vector<std::int64_t> pixels_a;
  std::vector<std::int64_t> pixels_b;
  std::vector<std::int64_t> both;  // ids_a.size() x ids_b.size()

  std::int64_t shared(std::size_t a, std::size_t b) const { return both[a * ids_b.size() + b]; }
};

// The overlap table of two CV_32SC1 label images of the same size; 0 is no segment.
OverlapTable count_overlap(const cv::Mat& labels_a, const cv::Mat& labels_b);

struct SegmentPair {
  std::size_t a = 0;  // index into ids_a
  std::size_t b = 0;  // index into ids_b
  double overlap = 0.0;
};

// The one-to-one pairing of largest total overlap; pairs that share no pixel or whose overlap is
// not above `min_overlap` are dropped. Sorted by a.
std::vector<SegmentPair> match_segments(const OverlapTable& table, OverlapMeasure measure,
                                        double min_overlap);

}  // namespace facet::eval
