// .oni recordings written by OniDepthWriter and played back by OpenNI2's own file driver through
// io.openni2: the frames, their order, times and field of view survive the round trip, and the
// stream ends (or loops) at the end of the file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "openni2/oni_sink.hpp"
#include "openni2/oni_writer.hpp"
#include "openni2/openni_source.hpp"
#include "temp_dir.hpp"

namespace facet::openni2 {
namespace {

using ::testing::HasSubstr;
using Runner = facet::testing::StageRunner<OpenNi2Source>;

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr std::uint64_t kPeriodUs = 33'333;

// Frame i: a ramp that differs from frame to frame, and a hole (0) at a frame-dependent pixel.
cv::Mat test_frame(int i) {
  cv::Mat depth(kHeight, kWidth, CV_16UC1);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x)
      depth.at<std::uint16_t>(y, x) = static_cast<std::uint16_t>(500 + 10 * x + 7 * y + 100 * i);
  }
  depth.at<std::uint16_t>(i % kHeight, i % kWidth) = 0;
  return depth;
}

std::string write_recording(const test::TempDir& dir, int frames) {
  const auto file = dir / "take.oni";
  OniDepthWriter writer(file, {kWidth, kHeight, 30, 1.0, 0.8});
  for (int i = 0; i < frames; ++i)
    writer.add(test_frame(i), 1'000'000 + static_cast<std::uint64_t>(i) * kPeriodUs);
  writer.finish();
  return file.string();
}

TEST(OniPlayback, EveryFrameComesBackInOrderWithItsTimeAndThenTheStreamEnds) {
  test::TempDir dir("facet-oni");
  const int frames = 5;
  Runner runner({{"uri", write_recording(dir, frames)}});
  for (int i = 0; i < frames; ++i) {
    runner.run();
    ASSERT_FALSE(runner.at_end_of_stream()) << "frame " << i;
    const auto& depth = runner.output<DepthImage>("depth");
    ASSERT_EQ(depth.depth.type(), CV_16UC1);
    ASSERT_EQ(depth.depth.size(), cv::Size(kWidth, kHeight));
    EXPECT_EQ(cv::norm(depth.depth, test_frame(i), cv::NORM_INF), 0.0) << "frame " << i;
    EXPECT_EQ(depth.frame.index, i);
    EXPECT_EQ(depth.frame.timestamp_ns,
              static_cast<std::int64_t>(1'000'000 + i * kPeriodUs) * 1000);
  }
  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());
}

TEST(OniPlayback, IntrinsicsComeFromTheRecordedFieldOfView) {
  test::TempDir dir("facet-oni");
  Runner runner({{"uri", write_recording(dir, 2)}});
  runner.run();
  const auto& camera = runner.output<DepthImage>("depth").camera;
  EXPECT_NEAR(camera.fx, 0.5 * kWidth / std::tan(0.5), 1e-3);  // hfov 1.0 rad, stored as float
  EXPECT_NEAR(camera.fy, 0.5 * kHeight / std::tan(0.4), 1e-3);
  EXPECT_DOUBLE_EQ(camera.cx, 0.5 * (kWidth - 1));
  EXPECT_EQ(camera.width, kWidth);
}

TEST(OniPlayback, LoopStartsAgainAfterTheLastFrame) {
  test::TempDir dir("facet-oni");
  Runner runner({{"uri", write_recording(dir, 3)}, {"loop", true}});
  std::vector<double> first_pixels;
  for (int i = 0; i < 7; ++i) {
    runner.run();
    ASSERT_FALSE(runner.at_end_of_stream()) << i;
    first_pixels.push_back(runner.output<DepthImage>("depth").depth.at<std::uint16_t>(0, 1));
  }
  // Frames 0, 1, 2, 0, 1, 2, 0 of the file.
  for (int i = 0; i < 7; ++i)
    EXPECT_EQ(first_pixels[i], test_frame(i % 3).at<std::uint16_t>(0, 1)) << i;
}

TEST(OniPlayback, AModeRequestMustMatchTheRecording) {
  test::TempDir dir("facet-oni");
  Runner runner({{"uri", write_recording(dir, 2)}, {"width", std::int64_t{640}}});
  try {
    runner.run();
    ADD_FAILURE() << "played a 64x48 recording as 640 wide";
  } catch (const StageError& error) {
    EXPECT_THAT(error.what(), HasSubstr("take.oni"));
    EXPECT_THAT(error.what(), HasSubstr("64x48 @ 30 fps, 1 mm"));
  }
}

TEST(OniPlayback, TheWriterRefusesFramesOfAnotherSizeNamingTheFile) {
  test::TempDir dir("facet-oni");
  OniDepthWriter writer(dir / "take.oni", {kWidth, kHeight, 30, 1.0, 0.8});
  try {
    writer.add(cv::Mat(10, 10, CV_16UC1, cv::Scalar(1)), 0);
    ADD_FAILURE() << "accepted a 10x10 frame";
  } catch (const StageError& error) {
    EXPECT_THAT(error.what(), HasSubstr("take.oni"));
    EXPECT_THAT(error.what(), HasSubstr("64x48"));
  }
}

DepthImage stream_frame(int i) {
  DepthImage image;
  image.depth = test_frame(i);
  image.frame.index = i;
  image.frame.timestamp_ns = static_cast<std::int64_t>(i) * 40'000'000;  // 25 Hz
  image.camera = {70.0, 72.0, 31.5, 23.5, kWidth, kHeight};
  return image;
}

TEST(OniPlayback, IoOniRecordsAStreamThatIoOpenNi2PlaysBackWithItsCamera) {
  test::TempDir dir("facet-oni");
  const std::string file = (dir / "stream.oni").string();
  {
    facet::testing::StageRunner<OniSink> sink({{"path", file}, {"fps", std::int64_t{25}}});
    for (int i = 0; i < 4; ++i) {
      sink.set_input("depth", Packet::make(stream_frame(i)));
      sink.run();
    }
    EXPECT_TRUE(sink.warnings().empty());
  }  // closing the sink completes the file

  Runner source({{"uri", file}});
  for (int i = 0; i < 4; ++i) {
    source.run();
    ASSERT_FALSE(source.at_end_of_stream()) << i;
    const auto& depth = source.output<DepthImage>("depth");
    EXPECT_EQ(cv::norm(depth.depth, test_frame(i), cv::NORM_INF), 0.0) << i;
    EXPECT_EQ(depth.frame.timestamp_ns, static_cast<std::int64_t>(i) * 40'000'000);
    // The field of view the file holds gives back the focal lengths (stored as float angles).
    EXPECT_NEAR(depth.camera.fx, 70.0, 1e-3);
    EXPECT_NEAR(depth.camera.fy, 72.0, 1e-3);
  }
  source.run();
  EXPECT_TRUE(source.at_end_of_stream());
}

TEST(OniPlayback, IoOniRefusesAFrameOfAnotherSizeNamingTheFile) {
  test::TempDir dir("facet-oni");
  const std::string file = (dir / "stream.oni").string();
  facet::testing::StageRunner<OniSink> sink({{"path", file}});
  sink.set_input("depth", Packet::make(stream_frame(0)));
  sink.run();
  DepthImage small = stream_frame(1);
  small.depth = cv::Mat(8, 8, CV_16UC1, cv::Scalar(900));
  small.camera.width = 8;  // an 8x8 camera's frame: a well-formed image, but not this stream's
  small.camera.height = 8;
  sink.set_input("depth", Packet::make(small));
  try {
    sink.run();
    ADD_FAILURE() << "recorded an 8x8 frame into a 64x48 stream";
  } catch (const StageError& error) {
    EXPECT_THAT(error.what(), HasSubstr(file));
  }
}

TEST(OniPlayback, IoOniCreatesItsFolderOrNamesWhyItCannot) {
  test::TempDir dir("facet-oni");
  const auto nested = dir / "takes" / "today" / "a.oni";
  {
    facet::testing::StageRunner<OniSink> sink({{"path", nested.string()}});
    sink.set_input("depth", Packet::make(stream_frame(0)));
    sink.run();
  }
  EXPECT_TRUE(std::filesystem::is_regular_file(nested));

  std::ofstream(dir / "plain") << "a file, not a folder";
  const std::string blocked = (dir / "plain" / "a.oni").string();
  facet::testing::StageRunner<OniSink> sink({{"path", blocked}});
  sink.set_input("depth", Packet::make(stream_frame(0)));
  try {
    sink.run();
    ADD_FAILURE() << "wrote below a plain file";
  } catch (const StageError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'" + blocked + "'"));
    EXPECT_THAT(error.what(), HasSubstr("cannot create folder"));
  }
}

TEST(OniPlayback, FieldOfViewOfAPinholeCamera) {
  const CameraIntrinsics camera{525.0, 525.0, 319.5, 239.5, 640, 480};
  EXPECT_NEAR(horizontal_fov_rad(camera), 2.0 * std::atan(320.0 / 525.0), 1e-12);
  EXPECT_NEAR(vertical_fov_rad(camera), 2.0 * std::atan(240.0 / 525.0), 1e-12);
  EXPECT_EQ(horizontal_fov_rad(CameraIntrinsics{}), 0.0);
}

}  // namespace
}  // namespace facet::openni2
