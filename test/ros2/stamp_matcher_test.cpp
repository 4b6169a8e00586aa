// Pairing depth images with the camera_info of their stamp.

#include "ros2/stamp_matcher.hpp"

#include <gtest/gtest.h>

namespace facet::ros2 {
namespace {

ReceivedImage image(std::int64_t stamp_ns) {
  ReceivedImage received;
  received.stamp_ns = stamp_ns;
  received.depth = cv::Mat(1, 1, CV_16UC1, cv::Scalar(static_cast<double>(stamp_ns)));
  return received;
}

CameraIntrinsics camera(double fx) {
  return {fx, fx, 0.5, 0.5, 1, 1};
}

TEST(StampMatcher, AnImageWaitsForTheInfoOfItsStamp) {
  StampMatcher matcher(4, 8);
  matcher.add_image(image(10));
  EXPECT_FALSE(matcher.take_oldest());
  matcher.add_info(10, camera(500.0));
  const auto frame = matcher.take_oldest();
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->image.stamp_ns, 10);
  EXPECT_EQ(frame->camera.fx, 500.0);
  EXPECT_EQ(matcher.take_dropped_count(), 0u);
}

TEST(StampMatcher, OldestTakesEveryFrameInOrder) {
  StampMatcher matcher(4, 8);
  for (std::int64_t stamp : {1, 2, 3}) {
    matcher.add_info(stamp, camera(static_cast<double>(stamp)));
    matcher.add_image(image(stamp));
  }
  for (std::int64_t stamp : {1, 2, 3}) {
    const auto frame = matcher.take_oldest();
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->image.stamp_ns, stamp);
    EXPECT_EQ(frame->camera.fx, static_cast<double>(stamp));
  }
  EXPECT_FALSE(matcher.take_oldest());
}

TEST(StampMatcher, AnImageWhoseInfoWasLostIsDroppedOnceANewerInfoCame) {
  StampMatcher matcher(4, 8);
  matcher.add_image(image(1));
  matcher.add_image(image(2));
  matcher.add_info(2, camera(2.0));  // the info of stamp 1 never comes
  const auto frame = matcher.take_oldest();
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->image.stamp_ns, 2);
  EXPECT_EQ(matcher.take_dropped_count(), 1u);
  EXPECT_EQ(matcher.unmatched_total(), 1u);
}

TEST(StampMatcher, NewestPassesOverOlderFramesAndCountsThem) {
  StampMatcher matcher(8, 8);
  for (std::int64_t stamp : {1, 2, 3}) {
    matcher.add_info(stamp, camera(1.0));
    matcher.add_image(image(stamp));
  }
  matcher.add_image(image(4));  // its info is still on the way
  const auto frame = matcher.take_newest();
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->image.stamp_ns, 3);
  EXPECT_EQ(matcher.take_dropped_count(), 2u);
  EXPECT_EQ(matcher.unmatched_total(), 0u);
  EXPECT_EQ(matcher.pending_images(), 1u);
  matcher.add_info(4, camera(1.0));
  const auto next = matcher.take_newest();
  ASSERT_TRUE(next);
  EXPECT_EQ(next->image.stamp_ns, 4);
}

TEST(StampMatcher, ImagesWithoutAnyInfoAreBoundedAndCounted) {
  StampMatcher matcher(2, 8);
  for (std::int64_t stamp : {1, 2, 3, 4, 5})
    matcher.add_image(image(stamp));
  EXPECT_EQ(matcher.pending_images(), 2u);
  EXPECT_EQ(matcher.unmatched_total(), 3u);
  EXPECT_FALSE(matcher.take_oldest());
  EXPECT_FALSE(matcher.take_newest());
}

}  // namespace
}  // namespace facet::ros2
