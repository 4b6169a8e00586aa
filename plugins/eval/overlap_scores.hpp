#pragma once
// Overlap scores of one predicted label image against its ground truth, as the unseen-object
// segmentation literature reports them (UOIS, OSD): one-to-one matching of ground-truth objects
// and predicted segments by IoU (Hungarian), then precision, recall and F-measure over pixels,
// the share of objects segmented with F >= 0.75, and over- and under-segmentation counts.

#include <cstdint>
#include <opencv2/core.hpp>
#include <set>

namespace facet::eval {

struct OverlapOptions {
  // Ground-truth ids treated as background (0 always is), e.g. the table of OSD's labels.
  std::set<std::int32_t> truth_background;
  // Ground-truth objects with fewer pixels are left out; their pixels count in neither image.
  std::int64_t min_truth_pixels = 0;
  // A matched object is "segmented" when the pair's F-measure 2|G&S| / (|G|+|S|) is >= this.
  double segmented_f = 0.75;
  // A segment "covers" an object when it holds at least this share of the object's pixels.
  double cover = 0.2;
};

struct OverlapScores {
  // Pixel overlap of the matched pairs over all predicted object pixels / all truth object pixels.
  double precision = 0.0;
  double recall = 0.0;
  double f = 0.0;
  std::int64_t truth_objects = 0;
  std::int64_t segments = 0;
  std::int64_t matched = 0;              // assigned pairs that overlap
  std::int64_t objects_segmented = 0;    // matched objects with pair F >= segmented_f
  double objects_segmented_ratio = 0.0;  // of the truth objects; 0 without any
  std::int64_t over_segmented = 0;       // objects covered by 2+ segments
  std::int64_t under_segmenting = 0;     // segments covering 2+ objects
  std::int64_t merged_objects = 0;       // objects covered by an under-segmenting segment
  double mean_iou = 0.0;                 // over truth objects, 0 for an unmatched one
};

// `truth` and `predicted`: single-channel integer label images (CV_8U, CV_16U or CV_32S) of the
// same size, 0 = background. Ids are arbitrary on both sides. Throws std::invalid_argument on
// mismatching sizes or unsupported types.
OverlapScores score_overlap(const cv::Mat& truth, const cv::Mat& predicted,
                            const OverlapOptions& options = {});

}  // namespace facet::eval
