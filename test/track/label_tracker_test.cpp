#include "track/label_tracker.hpp"

#include <gtest/gtest.h>

#include <map>

#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "label_boxes.hpp"
#include "track/track_labels.hpp"

namespace facet::track {
namespace {

using Box = facet::test::LabelBox;

// One 60x40 frame of rectangular segments.
cv::Mat frame(std::initializer_list<Box> boxes) {
  return facet::test::label_boxes({60, 40}, boxes);
}

// The track id at the centre of `rect` (where the object is in that frame).
std::int32_t id_at(const cv::Mat& tracked, const cv::Rect& rect) {
  return tracked.at<std::int32_t>(rect.y + rect.height / 2, rect.x + rect.width / 2);
}

TEST(LabelTracker, IdsStayWhenObjectsMoveALittleAndInputIdsChange) {
  LabelTracker tracker({});
  const cv::Mat first = tracker.update(frame({{5, {2, 2, 10, 10}}, {9, {30, 5, 12, 20}}}));
  const std::int32_t a = id_at(first, {2, 2, 10, 10});
  const std::int32_t b = id_at(first, {30, 5, 12, 20});
  EXPECT_NE(a, b);
  EXPECT_GT(a, 0);
  // Both move by two pixels; the segmenter numbers them the other way round.
  const cv::Mat second = tracker.update(frame({{1, {32, 6, 12, 20}}, {2, {4, 3, 10, 10}}}));
  EXPECT_EQ(id_at(second, {4, 3, 10, 10}), a);
  EXPECT_EQ(id_at(second, {32, 6, 12, 20}), b);
  EXPECT_EQ(tracker.largest_id(), 2);
  EXPECT_EQ(second.at<std::int32_t>(0, 0), 0);  // background stays background
}

TEST(LabelTracker, NewObjectGetsANewIdNeverUsedBefore) {
  LabelTracker tracker({.memory_frames = 0});
  tracker.update(frame({{1, {2, 2, 10, 10}}, {2, {30, 5, 12, 20}}}));
  // The second object disappears and is forgotten at once.
  tracker.update(frame({{1, {2, 2, 10, 10}}}));
  // A new object where the forgotten one was: it must not inherit id 2.
  const cv::Mat third = tracker.update(frame({{1, {2, 2, 10, 10}}, {7, {30, 5, 12, 20}}}));
  EXPECT_EQ(id_at(third, {2, 2, 10, 10}), 1);
  EXPECT_EQ(id_at(third, {30, 5, 12, 20}), 3);
  // A new object somewhere else, too.
  const cv::Mat fourth =
      tracker.update(frame({{1, {2, 2, 10, 10}}, {7, {30, 5, 12, 20}}, {8, {15, 28, 8, 8}}}));
  EXPECT_EQ(id_at(fourth, {15, 28, 8, 8}), 4);
}

TEST(LabelTracker, LostObjectFoundAgainWithinTheMemoryKeepsItsId) {
  LabelTracker tracker({.memory_frames = 3});
  const Box steady{1, {2, 2, 10, 10}};
  const Box hidden{2, {30, 5, 12, 20}};
  const std::int32_t id = id_at(tracker.update(frame({steady, hidden})), hidden.rect);
  for (int lost = 0; lost < 3; ++lost)
    tracker.update(frame({steady}));
  const cv::Mat back = tracker.update(frame({steady, {4, {31, 5, 12, 20}}}));
  EXPECT_EQ(id_at(back, {31, 5, 12, 20}), id);
  // Lost for longer than the memory: a new id.
  for (int lost = 0; lost < 4; ++lost)
    tracker.update(frame({steady}));
  const cv::Mat late = tracker.update(frame({steady, hidden}));
  EXPECT_EQ(id_at(late, hidden.rect), 3);
}

TEST(LabelTracker, SmallOverlapStartsANewTrack) {
  LabelTracker tracker({.min_overlap = 0.5});
  tracker.update(frame({{1, {0, 0, 10, 10}}}));
  // Moved 8 of 10 columns: 20 % shared, below 0.5.
  const cv::Mat moved = tracker.update(frame({{1, {8, 0, 10, 10}}}));
  EXPECT_EQ(id_at(moved, {8, 0, 10, 10}), 2);
}

TEST(LabelTracker, OneToOneWhenAnObjectSplits) {
  LabelTracker tracker({});
  tracker.update(frame({{1, {0, 0, 20, 10}}}));
  const cv::Mat split = tracker.update(frame({{1, {0, 0, 14, 10}}, {2, {14, 0, 6, 10}}}));
  EXPECT_EQ(id_at(split, {0, 0, 14, 10}), 1);  // the larger part continues the track
  EXPECT_EQ(id_at(split, {14, 0, 6, 10}), 2);
}

TEST(LabelTracker, DeterministicForTheSameInput) {
  const std::vector<cv::Mat> frames = {
      frame({{1, {2, 2, 10, 10}}, {2, {30, 5, 12, 20}}, {3, {15, 28, 8, 8}}}),
      frame({{3, {3, 2, 10, 10}}, {1, {16, 28, 8, 8}}}),
      frame({{2, {3, 3, 10, 10}}, {4, {31, 5, 12, 20}}, {5, {15, 27, 8, 8}}})};
  LabelTracker once({.memory_frames = 2});
  LabelTracker again({.memory_frames = 2});
  for (const cv::Mat& labels : frames) {
    const cv::Mat a = once.update(labels);
    const cv::Mat b = again.update(labels);
    EXPECT_EQ(cv::countNonZero(a != b), 0);
  }
}

TEST(LabelTracker, StageOutputsTrackIdsAndRejectsSizeChanges) {
  testing::StageRunner<TrackLabels> runner;
  runner.set_input("labels",
                   Packet::make(LabelImage::counted(FrameHeader{}, frame({{7, {2, 2, 10, 10}}}))));
  runner.run();
  const LabelImage& out = runner.output<LabelImage>("labels");
  EXPECT_EQ(id_at(out.labels, {2, 2, 10, 10}), 1);
  EXPECT_EQ(out.count, 1);
  std::map<std::string, double> metrics;
  for (const auto& metric : runner.metrics())
    metrics[metric.name] = metric.value;
  EXPECT_EQ(metrics.at("new_tracks"), 1.0);
  EXPECT_EQ(metrics.at("tracks"), 1.0);
  LabelImage smaller;
  smaller.labels = cv::Mat::zeros(10, 10, CV_32SC1);
  runner.set_input("labels", Packet::make(smaller));
  EXPECT_THROW(runner.run(), StageError);
}

}  // namespace
}  // namespace facet::track
