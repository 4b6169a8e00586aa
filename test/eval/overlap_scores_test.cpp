// Overlap scores on small hand-made label images; every expected value is worked out by hand
// from the definitions in overlap_scores.hpp.
#include "eval/overlap_scores.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace facet::eval {
namespace {

// An 8 x 4 image whose columns carry the given ids (one id per column).
cv::Mat columns(std::initializer_list<int> ids) {
  cv::Mat labels(4, static_cast<int>(ids.size()), CV_32SC1);
  int x = 0;
  for (const int id : ids) {
    labels.col(x++).setTo(id);
  }
  return labels;
}

TEST(ScoreOverlap, PerfectSegmentationWithOtherIds) {
  const auto scores =
      score_overlap(columns({1, 1, 1, 2, 2, 0, 0, 0}), columns({7, 7, 7, 3, 3, 0, 0, 0}));
  EXPECT_DOUBLE_EQ(scores.precision, 1.0);
  EXPECT_DOUBLE_EQ(scores.recall, 1.0);
  EXPECT_DOUBLE_EQ(scores.f, 1.0);
  EXPECT_EQ(scores.truth_objects, 2);
  EXPECT_EQ(scores.segments, 2);
  EXPECT_EQ(scores.matched, 2);
  EXPECT_EQ(scores.objects_segmented, 2);
  EXPECT_DOUBLE_EQ(scores.objects_segmented_ratio, 1.0);
  EXPECT_EQ(scores.over_segmented, 0);
  EXPECT_EQ(scores.under_segmenting, 0);
  EXPECT_DOUBLE_EQ(scores.mean_iou, 1.0);
}

TEST(ScoreOverlap, OverSegmentationAndBackgroundPixelsInASegment) {
  // Object 1 (16 px) split into 5 and 6 (8 px each); object 2 (8 px) inside segment 7, which
  // also takes 8 background pixels. Matches: 1-5 or 1-6 (IoU 0.5), 2-7 (IoU 0.5).
  // P = (8 + 8) / 32, R = 16 / 24, F = 2PR / (P + R) = 4/7.
  const auto scores =
      score_overlap(columns({1, 1, 1, 1, 2, 2, 0, 0}), columns({5, 5, 6, 6, 7, 7, 7, 7}));
  EXPECT_DOUBLE_EQ(scores.precision, 0.5);
  EXPECT_DOUBLE_EQ(scores.recall, 2.0 / 3.0);
  EXPECT_NEAR(scores.f, 4.0 / 7.0, 1e-12);
  EXPECT_EQ(scores.matched, 2);
  // Pair F: 2*8/(16+8) = 0.667 and 2*8/(8+16) = 0.667, both below 0.75.
  EXPECT_EQ(scores.objects_segmented, 0);
  EXPECT_EQ(scores.over_segmented, 1);
  EXPECT_EQ(scores.under_segmenting, 0);
  EXPECT_DOUBLE_EQ(scores.mean_iou, 0.5);
}

TEST(ScoreOverlap, UnderSegmentationMergesObjects) {
  // One segment over objects 1 (12 px) and 2 (8 px): matched to 1, 2 unmatched.
  const auto scores =
      score_overlap(columns({1, 1, 1, 2, 2, 0, 0, 0}), columns({4, 4, 4, 4, 4, 0, 0, 0}));
  EXPECT_EQ(scores.matched, 1);
  EXPECT_DOUBLE_EQ(scores.precision, 12.0 / 20.0);
  EXPECT_DOUBLE_EQ(scores.recall, 12.0 / 20.0);
  EXPECT_EQ(scores.under_segmenting, 1);
  EXPECT_EQ(scores.merged_objects, 2);
  EXPECT_EQ(scores.over_segmented, 0);
  // Pair F of 1-4: 2*12/(12+20) = 0.75, exactly the threshold (>=).
  EXPECT_EQ(scores.objects_segmented, 1);
  EXPECT_DOUBLE_EQ(scores.objects_segmented_ratio, 0.5);
  EXPECT_DOUBLE_EQ(scores.mean_iou, (12.0 / 20.0) / 2.0);
}

TEST(ScoreOverlap, MissingObject) {
  const auto scores =
      score_overlap(columns({1, 1, 2, 2, 0, 0, 0, 0}), columns({9, 9, 0, 0, 0, 0, 0, 0}));
  EXPECT_DOUBLE_EQ(scores.precision, 1.0);
  EXPECT_DOUBLE_EQ(scores.recall, 0.5);
  EXPECT_NEAR(scores.f, 2.0 / 3.0, 1e-12);
  EXPECT_EQ(scores.objects_segmented, 1);
  EXPECT_DOUBLE_EQ(scores.objects_segmented_ratio, 0.5);
}

TEST(ScoreOverlap, CoverThresholdDecidesOverSegmentation) {
  // Object 1 is 10 columns; segment 3 holds 1 column (10 %), below the default cover of 20 %.
  const cv::Mat truth = columns({1, 1, 1, 1, 1, 1, 1, 1, 1, 1});
  const cv::Mat predicted = columns({2, 2, 2, 2, 2, 2, 2, 2, 2, 3});
  EXPECT_EQ(score_overlap(truth, predicted).over_segmented, 0);
  OverlapOptions loose;
  loose.cover = 0.1;
  EXPECT_EQ(score_overlap(truth, predicted, loose).over_segmented, 1);
}

TEST(ScoreOverlap, EmptyPrediction) {
  const auto scores = score_overlap(columns({1, 1, 0, 0}), columns({0, 0, 0, 0}));
  EXPECT_DOUBLE_EQ(scores.precision, 1.0);
  EXPECT_DOUBLE_EQ(scores.recall, 0.0);
  EXPECT_DOUBLE_EQ(scores.f, 0.0);
  EXPECT_EQ(scores.truth_objects, 1);
  EXPECT_EQ(scores.segments, 0);
}

TEST(ScoreOverlap, SegmentsWithoutTruthObjects) {
  const auto scores = score_overlap(columns({0, 0, 0, 0}), columns({1, 1, 2, 0}));
  EXPECT_DOUBLE_EQ(scores.precision, 0.0);
  EXPECT_DOUBLE_EQ(scores.recall, 1.0);
  EXPECT_DOUBLE_EQ(scores.f, 0.0);
  const auto nothing = score_overlap(columns({0, 0}), columns({0, 0}));
  EXPECT_DOUBLE_EQ(nothing.f, 1.0);
}

TEST(ScoreOverlap, TruthBackgroundIdsAreNotObjects) {
  // Truth 1 is a table; as background it is no object, but a segment on it still counts in P.
  OverlapOptions options;
  options.truth_background = {1};
  const auto scores = score_overlap(columns({1, 1, 2, 2}), columns({5, 5, 6, 6}), options);
  EXPECT_EQ(scores.truth_objects, 1);
  EXPECT_DOUBLE_EQ(scores.recall, 1.0);
  EXPECT_DOUBLE_EQ(scores.precision, 0.5);
}

TEST(ScoreOverlap, SmallTruthObjectsAreIgnoredInBothImages) {
  // Object 2 (4 px) is below 5 px: its pixels leave both images, so segment 6 disappears too.
  OverlapOptions options;
  options.min_truth_pixels = 5;
  const auto scores = score_overlap(columns({1, 1, 2, 0}), columns({5, 5, 6, 0}), options);
  EXPECT_EQ(scores.truth_objects, 1);
  EXPECT_EQ(scores.segments, 1);
  EXPECT_DOUBLE_EQ(scores.f, 1.0);
}

TEST(ScoreOverlap, AcceptsSixteenBitLabels) {
  cv::Mat truth;
  cv::Mat predicted;
  columns({1, 1, 0, 0}).convertTo(truth, CV_16U);
  columns({3, 3, 3, 0}).convertTo(predicted, CV_8U);
  EXPECT_DOUBLE_EQ(score_overlap(truth, predicted).precision, 8.0 / 12.0);
}

TEST(ScoreOverlap, RejectsMismatchingSizesAndTypes) {
  EXPECT_THROW(score_overlap(columns({1, 1}), columns({1, 1, 1})), std::invalid_argument);
  EXPECT_THROW(score_overlap(cv::Mat(4, 2, CV_32FC1, cv::Scalar(1)), columns({1, 1})),
               std::invalid_argument);
}

}  // namespace
}  // namespace facet::eval
