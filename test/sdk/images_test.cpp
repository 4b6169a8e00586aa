// The image types keep their format: the factories refuse what breaks it, format_error() says what
// is wrong with an image built field by field, and the framework checks every output a stage
// writes and every input a test feeds (facet/types/images.hpp).
#include "facet/types/images.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>

#include "facet/context.hpp"
#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/geometry.hpp"

namespace {

using facet::DepthImage;
using facet::EdgeImage;
using facet::FrameHeader;
using facet::LabelImage;
using facet::NormalImage;
using facet::PointImage;

FrameHeader frame_of_size(int width, int height) {
  FrameHeader header;
  header.frame.index = 12;
  header.frame.stem = "learn12";
  header.frame.timestamp_ns = 34;
  header.camera = {.fx = 525.0,
                   .fy = 525.0,
                   .cx = width / 2.0,
                   .cy = height / 2.0,
                   .width = width,
                   .height = height};
  return header;
}

template <class Call>
std::string invalid_argument_of(Call call) {
  try {
    call();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "no error";
}

TEST(Images, FactoriesInheritTheFrameAndTheCamera) {
  const FrameHeader input = frame_of_size(4, 3);
  const DepthImage depth = DepthImage::make(input, cv::Mat(3, 4, CV_16UC1, cv::Scalar(900)));
  EXPECT_EQ(depth.frame.index, 12);
  EXPECT_EQ(depth.frame.stem, "learn12");
  EXPECT_EQ(depth.frame.timestamp_ns, 34);
  EXPECT_EQ(depth.camera.width, 4);
  EXPECT_DOUBLE_EQ(depth.camera.fx, 525.0);
  const PointImage points = PointImage::make(depth, cv::Mat(3, 4, CV_32FC3));
  EXPECT_EQ(points.frame.stem, "learn12");
  const auto objects = facet::of_frame<facet::ObjectList>(points);
  EXPECT_EQ(objects.frame.index, 12);
  EXPECT_EQ(objects.camera.height, 3);
  EXPECT_TRUE(objects.objects.empty());
}

TEST(Images, DepthTakesMillimetresOrMetresOnly) {
  const FrameHeader input = frame_of_size(4, 3);
  EXPECT_TRUE(DepthImage::make(input, cv::Mat(3, 4, CV_16UC1)).in_millimetres());
  EXPECT_FALSE(DepthImage::make(input, cv::Mat(3, 4, CV_32FC1)).in_millimetres());
  EXPECT_EQ(invalid_argument_of([&] { DepthImage::make(input, cv::Mat(3, 4, CV_8UC1)); }),
            "depth is CV_8UC1, must be CV_16UC1 (mm) or CV_32FC1 (m)");
  EXPECT_EQ(invalid_argument_of([&] { DepthImage::make(input, cv::Mat()); }), "depth is empty");
}

TEST(Images, SizeMustMatchAKnownCamera) {
  EXPECT_EQ(invalid_argument_of(
                [&] { PointImage::make(frame_of_size(640, 480), cv::Mat(240, 320, CV_32FC3)); }),
            "points is 320x240, its camera's intrinsics are 640x480");
  // Without intrinsics (a synthetic test image, a host that knows none) any size is accepted.
  EXPECT_NO_THROW(PointImage::make(FrameHeader{}, cv::Mat(240, 320, CV_32FC3)));
}

TEST(Images, AViewIntoALargerImageIsRefused) {
  const cv::Mat whole(6, 8, CV_32FC3, cv::Scalar::all(0.0));
  const cv::Mat view = whole(cv::Rect(1, 1, 4, 3));
  ASSERT_FALSE(view.isContinuous());
  EXPECT_EQ(invalid_argument_of([&] { NormalImage::make(FrameHeader{}, view); }),
            "normals is not continuous (a view into a larger image); clone() it");
  EXPECT_NO_THROW(NormalImage::make(FrameHeader{}, view.clone()));
}

TEST(Images, EdgeScoreAndMaskAreOneSize) {
  const FrameHeader none;
  EXPECT_NO_THROW(EdgeImage::make(none, cv::Mat(3, 4, CV_32FC1), cv::Mat(3, 4, CV_8UC1)));
  EXPECT_EQ(invalid_argument_of(
                [&] { EdgeImage::make(none, cv::Mat(3, 4, CV_32FC1), cv::Mat(3, 5, CV_8UC1)); }),
            "score (4x3) and mask (5x3) differ in size");
  EXPECT_EQ(invalid_argument_of(
                [&] { EdgeImage::make(none, cv::Mat(3, 4, CV_32FC1), cv::Mat(3, 4, CV_32FC1)); }),
            "mask is CV_32FC1, must be CV_8UC1");
}

TEST(Images, LabelIdsLieWithinTheirCount) {
  cv::Mat ids(2, 3, CV_32SC1, cv::Scalar(0));
  ids.at<std::int32_t>(0, 1) = 2;
  ids.at<std::int32_t>(1, 2) = 5;
  EXPECT_EQ(LabelImage::make(FrameHeader{}, ids, 5).count, 5);
  EXPECT_EQ(LabelImage::make(FrameHeader{}, ids, 9).count, 9);  // ids in between may be unused
  EXPECT_EQ(invalid_argument_of([&] { LabelImage::make(FrameHeader{}, ids, 4); }),
            "labels hold the id 5, above their count 4");
  EXPECT_EQ(invalid_argument_of([&] { LabelImage::make(FrameHeader{}, ids, -1); }),
            "count is -1, must be 0 or more");
  ids.at<std::int32_t>(0, 0) = -3;
  EXPECT_EQ(invalid_argument_of([&] { LabelImage::make(FrameHeader{}, ids, 5); }),
            "labels hold the id -3; ids are 0 (background) or 1..count");
  EXPECT_EQ(
      invalid_argument_of([&] { LabelImage::make(FrameHeader{}, cv::Mat(2, 3, CV_16UC1), 0); }),
      "labels is CV_16UC1, must be CV_32SC1");
}

TEST(Images, CountedTakesTheLargestId) {
  cv::Mat ids(2, 3, CV_32SC1, cv::Scalar(0));
  EXPECT_EQ(LabelImage::counted(FrameHeader{}, ids).count, 0);
  ids.at<std::int32_t>(1, 0) = 7;
  EXPECT_EQ(LabelImage::counted(FrameHeader{}, ids).count, 7);
  ids.at<std::int32_t>(0, 2) = -1;  // no count makes a negative id valid
  EXPECT_EQ(invalid_argument_of([&] { LabelImage::counted(FrameHeader{}, ids); }),
            "labels hold the id -1; ids are 0 (background) or 1..count");
}

// The id check reads the ids as unsigned (one comparison finds both kinds of bad id); the extremes
// of int32 must still be told apart.
TEST(Images, TheExtremeIdsAreCheckedToo) {
  cv::Mat ids(1, 40, CV_32SC1, cv::Scalar(1));  // longer than one vector register
  ids.at<std::int32_t>(0, 37) = std::numeric_limits<std::int32_t>::min();
  EXPECT_EQ(invalid_argument_of([&] { LabelImage::make(FrameHeader{}, ids, 1); }),
            "labels hold the id -2147483648; ids are 0 (background) or 1..count");
  ids.at<std::int32_t>(0, 37) = std::numeric_limits<std::int32_t>::max();
  EXPECT_NO_THROW(LabelImage::make(FrameHeader{}, ids, std::numeric_limits<std::int32_t>::max()));
  EXPECT_EQ(invalid_argument_of([&] { LabelImage::make(FrameHeader{}, ids, 1000); }),
            "labels hold the id 2147483647, above their count 1000");
}

TEST(Images, APacketChecksItsPayloadsFormat) {
  DepthImage depth;  // built field by field, wrongly
  depth.depth = cv::Mat(2, 2, CV_8UC1);
  EXPECT_EQ(facet::Packet::make(depth).format_error(),
            "depth is CV_8UC1, must be CV_16UC1 (mm) or CV_32FC1 (m)");
  depth.depth = cv::Mat(2, 2, CV_16UC1);
  EXPECT_EQ(facet::Packet::make(depth).format_error(), "");
  EXPECT_EQ(facet::Packet().format_error(), "");  // empty: nothing to check
  // A type that promises no format has nothing to check.
  EXPECT_EQ(facet::Packet::make(facet::ObjectList{}).format_error(), "");
}

// Writes a label image whose ids exceed its count, as a stage that forgot a dropped segment would.
class WrongCount final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("test.wrong_count", "Writes labels above their count.")
        .input<DepthImage>("depth", "Any depth.")
        .output<LabelImage>("labels", "Labels 0..2 with a count of 1.");
  }
  explicit WrongCount(const facet::Params& /*params*/) {}
  void process(facet::ProcessContext& ctx) override {
    LabelImage labels;
    static_cast<FrameHeader&>(labels) = ctx.input<DepthImage>("depth");
    labels.labels = cv::Mat(2, 2, CV_32SC1, cv::Scalar(2));
    labels.count = 1;
    ctx.output("labels", std::move(labels));
  }
};

TEST(Images, AStageThatBreaksTheFormatFailsAtItsOutputPort) {
  facet::testing::StageRunner<WrongCount> runner;
  runner.set_input("depth",
                   facet::Packet::make(DepthImage::make(FrameHeader{}, cv::Mat(2, 2, CV_16UC1))));
  try {
    runner.run();
    FAIL() << "labels above their count were output";
  } catch (const facet::StageError& error) {
    EXPECT_EQ(std::string(error.what()),
              "output 'labels' (facet.LabelImage/1): labels hold the id 2, above their count 1");
  }
}

TEST(Images, ATestInputIsCheckedAsAGraphChecksIt) {
  facet::testing::StageRunner<WrongCount> runner;
  DepthImage depth;
  depth.depth = cv::Mat(2, 2, CV_64FC1);
  EXPECT_EQ(invalid_argument_of([&] { runner.set_input("depth", facet::Packet::make(depth)); }),
            "input 'depth' (facet.DepthImage/1): depth is CV_64FC1, must be CV_16UC1 (mm) or "
            "CV_32FC1 (m)");
}

}  // namespace
