#include "eval/stability_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "eval/frame_stability.hpp"
#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "label_boxes.hpp"

namespace facet::eval {
namespace {

using facet::testing::StageRunner;

using Box = facet::test::LabelBox;

// A 40x30 image with rectangular segments.
cv::Mat label_image(std::initializer_list<Box> boxes) {
  return facet::test::label_boxes({40, 30}, boxes);
}

// A flat wall 1 m away seen by a pinhole camera with f = 100 px: pixel (x, y) is the point
// ((x - 20) / 100, (y - 15) / 100, 1) m, so one pixel to the side is 10 mm.
cv::Mat wall_points() {
  cv::Mat points(30, 40, CV_32FC3);
  for (int y = 0; y < points.rows; ++y) {
    for (int x = 0; x < points.cols; ++x) {
      points.at<cv::Vec3f>(y, x) =
          cv::Vec3f(static_cast<float>(x - 20) / 100.0F, static_cast<float>(y - 15) / 100.0F, 1.0F);
    }
  }
  return points;
}

std::map<std::string, double> run_frame(StageRunner<StabilityEval>& runner, const cv::Mat& labels,
                                        const cv::Mat& points = {}) {
  runner.set_input("labels", Packet::make(LabelImage::counted(FrameHeader{}, labels)));
  if (!points.empty()) {
    PointImage cloud;
    cloud.points = points;
    runner.set_input("points", Packet::make(cloud));
  }
  runner.run();
  std::map<std::string, double> metrics;
  for (const auto& metric : runner.metrics())
    metrics[metric.name] = metric.value;
  return metrics;
}

TEST(StabilityEval, IdenticalFramesAreFullyStable) {
  StageRunner<StabilityEval> runner;
  const cv::Mat labels = label_image({{3, {2, 2, 10, 10}}, {7, {20, 5, 8, 12}}});
  EXPECT_EQ(run_frame(runner, labels, wall_points()).at("compared"), 0.0);
  for (int frame = 1; frame < 4; ++frame) {
    const auto metrics = run_frame(runner, labels, wall_points());
    EXPECT_EQ(metrics.at("compared"), 1.0);
    EXPECT_DOUBLE_EQ(metrics.at("overlap_avg_pct"), 100.0);
    EXPECT_DOUBLE_EQ(metrics.at("overlap_min_pct"), 100.0);
    EXPECT_DOUBLE_EQ(metrics.at("centroid_max_mm"), 0.0);
    EXPECT_EQ(metrics.at("spurious"), 0.0);
    EXPECT_EQ(metrics.at("spurious_total"), 0.0);
    EXPECT_EQ(metrics.at("segments"), 2.0);
    EXPECT_EQ(metrics.at("corresponding"), 2.0);
  }
}

TEST(StabilityEval, IdsNeedNotAgreeBetweenFrames) {
  StageRunner<StabilityEval> runner;
  run_frame(runner, label_image({{1, {2, 2, 10, 10}}, {2, {20, 5, 8, 12}}}));
  const auto metrics = run_frame(runner, label_image({{9, {2, 2, 10, 10}}, {4, {20, 5, 8, 12}}}));
  EXPECT_DOUBLE_EQ(metrics.at("overlap_min_pct"), 100.0);
  EXPECT_EQ(metrics.at("spurious"), 0.0);
  EXPECT_EQ(metrics.count("centroid_avg_mm"), 0u);  // no points connected
}

TEST(StabilityEval, SegmentSeenInOneFrameOnlyIsOneSpurious) {
  StageRunner<StabilityEval> runner;
  const Box steady{1, {2, 2, 10, 10}};
  run_frame(runner, label_image({steady}));
  auto metrics = run_frame(runner, label_image({steady, {2, {25, 20, 5, 5}}}));
  EXPECT_EQ(metrics.at("spurious"), 1.0);
  EXPECT_DOUBLE_EQ(metrics.at("spurious_pct"), 50.0);
  EXPECT_EQ(metrics.at("vanished"), 0.0);
  metrics = run_frame(runner, label_image({steady}));
  EXPECT_EQ(metrics.at("spurious"), 0.0);
  EXPECT_EQ(metrics.at("vanished"), 1.0);
  EXPECT_EQ(metrics.at("spurious_total"), 1.0);
  EXPECT_DOUBLE_EQ(metrics.at("overlap_avg_pct"), 100.0);
}

TEST(StabilityEval, MovingSegmentGivesOverlapAndCentroidDistanceInMillimetres) {
  StageRunner<StabilityEval> runner;
  run_frame(runner, label_image({{1, {4, 4, 10, 10}}}), wall_points());
  // Moved 2 px right: 80 of 100 pixels shared, mean ratio (0.8 + 0.8) / 2; 2 px = 20 mm.
  const auto metrics = run_frame(runner, label_image({{1, {6, 4, 10, 10}}}), wall_points());
  EXPECT_NEAR(metrics.at("overlap_avg_pct"), 80.0, 1e-9);
  EXPECT_NEAR(metrics.at("centroid_avg_px"), 2.0, 1e-9);
  EXPECT_NEAR(metrics.at("centroid_avg_mm"), 20.0, 1e-3);
  EXPECT_NEAR(metrics.at("centroid_max_mm"), 20.0, 1e-3);
}

TEST(StabilityEval, MeasuresDifferForSegmentsOfDifferentSize) {
  // Segment 10x10 shrinks to 10x5 inside it: mean ratio (50/100 + 50/50) / 2 = 75 %,
  // IoU 50 / 100 = 50 %.
  const cv::Mat before = label_image({{1, {4, 4, 10, 10}}});
  const cv::Mat after = label_image({{1, {4, 4, 10, 5}}});
  StabilityOptions options;
  EXPECT_NEAR(compare_frames(before, {}, after, {}, options).overlaps.at(0), 0.75, 1e-12);
  options.measure = OverlapMeasure::iou;
  EXPECT_NEAR(compare_frames(before, {}, after, {}, options).overlaps.at(0), 0.5, 1e-12);
  options.min_overlap = 0.6;
  const FrameStability strict = compare_frames(before, {}, after, {}, options);
  EXPECT_TRUE(strict.overlaps.empty());
  EXPECT_EQ(strict.spurious, 1);
}

TEST(StabilityEval, OneToOneWhenASegmentSplits) {
  // One segment splits into a large and a small part: the large part corresponds, the small one
  // is spurious.
  const cv::Mat before = label_image({{1, {0, 0, 20, 10}}});
  const cv::Mat after = label_image({{1, {0, 0, 15, 10}}, {2, {15, 0, 5, 10}}});
  const FrameStability frame = compare_frames(before, {}, after, {});
  ASSERT_EQ(frame.overlaps.size(), 1u);
  EXPECT_NEAR(frame.overlaps[0], 0.5 * (150.0 / 200.0 + 1.0), 1e-12);
  EXPECT_EQ(frame.spurious, 1);
}

TEST(StabilityEval, CentroidsUseOnlyValidPoints) {
  cv::Mat points = wall_points();
  // The right half of the segment has no depth in the second frame: its 3D centroid moves
  // 2.5 px = 25 mm to the left, its pixel centroid stays.
  cv::Mat holes = points.clone();
  holes(cv::Rect(9, 4, 5, 10)).setTo(cv::Vec3f(NAN, NAN, NAN));
  const cv::Mat labels = label_image({{1, {4, 4, 10, 10}}});
  const FrameStability frame = compare_frames(labels, points, labels, holes);
  ASSERT_EQ(frame.centroid_mm.size(), 1u);
  EXPECT_NEAR(frame.centroid_mm[0], 25.0, 1e-3);
  EXPECT_NEAR(frame.centroid_px[0], 0.0, 1e-12);
}

TEST(StabilityEval, BadInputIsAClearError) {
  StageRunner<StabilityEval> runner;
  run_frame(runner, label_image({{1, {4, 4, 10, 10}}}));
  LabelImage smaller;
  smaller.labels = cv::Mat::zeros(10, 10, CV_32SC1);
  runner.set_input("labels", Packet::make(smaller));
  EXPECT_THROW(runner.run(), StageError);
  EXPECT_THROW(StageRunner<StabilityEval>({{"measure", std::string("dice")}}), std::exception);
}

}  // namespace
}  // namespace facet::eval
