// The run's progress line: frame i of N, percent and time left when N is known.

#include "facet/framework/progress_text.hpp"

#include <gtest/gtest.h>

namespace facet {
namespace {

FrameEvent event(std::int64_t index, std::int64_t stream_frames) {
  return FrameEvent{index, "learn11", 31.2, stream_frames};
}

TEST(ProgressText, KnownLengthShowsFramesPercentAndTimeLeft) {
  // 12 of 45 frames in 6 s: 33 more at 0.5 s each.
  EXPECT_EQ(progress_text(event(11, 45), -1, 6.0),
            "frame 12/45   26%  learn11                     31.20 ms  0:17 left");
  // Hours once the time left is that long.
  EXPECT_EQ(progress_text(event(0, 10000), -1, 2.0).substr(0, 20), "frame 1/10000    0% ");
  EXPECT_NE(progress_text(event(0, 10000), -1, 2.0).find("5:33:18 left"), std::string::npos);
}

TEST(ProgressText, TheFrameLimitCutsTheLengthOrGivesOne) {
  EXPECT_EQ(expected_frames(event(0, 45), 10), 10);
  EXPECT_EQ(expected_frames(event(0, 45), 100), 45);
  EXPECT_EQ(expected_frames(event(0, 0), 100), 100);  // a camera run with --frames
  EXPECT_EQ(expected_frames(event(0, 0), -1), 0);
  EXPECT_NE(progress_text(event(4, 45), 10, 1.0).find("frame 5/10   50%"), std::string::npos);
}

TEST(ProgressText, UnknownLengthShowsTheFrameOnly) {
  EXPECT_EQ(progress_text(event(11, 0), -1, 6.0),
            "frame     12  learn11                     31.20 ms");
  // A source that delivers more than it announced does not show 110 %.
  EXPECT_EQ(progress_text(event(10, 10), -1, 1.0).find('%'), std::string::npos);
}

}  // namespace
}  // namespace facet
