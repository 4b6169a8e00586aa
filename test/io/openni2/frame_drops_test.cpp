// Counting the frames a live source never passed on, and when it says so.

#include "openni2/frame_drops.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace facet::openni2 {
namespace {

using ::testing::HasSubstr;

TEST(FrameDrops, ConsecutiveDeviceNumbersDropNothing) {
  FrameDrops drops;
  for (int index = 1; index <= 5; ++index)
    EXPECT_EQ(drops.passed_on(index), 0);
  EXPECT_EQ(drops.total(), 0);
  EXPECT_EQ(drops.warning(), std::nullopt);
}

TEST(FrameDrops, AGapInTheNumbersIsTheFramesBetween) {
  FrameDrops drops;
  EXPECT_EQ(drops.passed_on(10), 0);  // the first frame has nothing before it
  EXPECT_EQ(drops.passed_on(14), 3);
  EXPECT_EQ(drops.passed_on(15), 0);
  EXPECT_EQ(drops.passed_on(20), 4);
  EXPECT_EQ(drops.total(), 7);
}

TEST(FrameDrops, NumbersStartingAgainBeginANewCount) {
  FrameDrops drops;
  drops.passed_on(100);
  EXPECT_EQ(drops.passed_on(1), 0);  // a looping recording
  EXPECT_EQ(drops.passed_on(3), 1);
  EXPECT_EQ(drops.total(), 1);
}

TEST(FrameDrops, WarnsAtTheFirstDropThenAtMostOncePerPeriod) {
  FrameDrops drops(10);
  drops.passed_on(1);
  drops.passed_on(3);
  const auto first = drops.warning();
  ASSERT_TRUE(first.has_value());
  EXPECT_THAT(*first, HasSubstr("1 stale frame(s) dropped"));
  EXPECT_THAT(*first, HasSubstr("1 in all"));

  // More drops within the period: no warning until 10 frames were passed on since the last.
  std::int64_t index = 3;
  for (int frame = 0; frame < 9; ++frame) {
    index += 2;
    drops.passed_on(index);
    EXPECT_EQ(drops.warning(), std::nullopt) << frame;
  }
  drops.passed_on(index + 2);
  const auto second = drops.warning();
  ASSERT_TRUE(second.has_value());
  EXPECT_THAT(*second, HasSubstr("10 stale frame(s) dropped in the last 10 frames"));
  EXPECT_THAT(*second, HasSubstr("11 in all"));
  EXPECT_EQ(drops.warning(), std::nullopt);  // nothing new since
}

}  // namespace
}  // namespace facet::openni2
