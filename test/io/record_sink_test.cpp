// io.record: a stream recorded in the dataset layout replays through io.frames unchanged.
#include "io/record_sink.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "io/frames_source.hpp"
#include "io/intrinsics_file.hpp"
#include "stage_test_support.hpp"

namespace {

using facet::DepthImage;
using facet::LabelImage;
using facet::Packet;
using facet::ParamValue;
using facet::io::FramesSource;
using facet::io::RecordSink;
using facet::test::data_dir;
using facet::test::expect_stage_error;
using facet::test::TempDir;
using Source = facet::testing::StageRunner<FramesSource>;
using Recorder = facet::testing::StageRunner<RecordSink>;

struct Frame {
  DepthImage depth;
  LabelImage labels;
};

std::vector<Frame> read_all(const std::filesystem::path& dataset) {
  Source source({{"path", ParamValue(dataset.string())}});
  std::vector<Frame> frames;
  for (;;) {
    source.run();
    if (source.at_end_of_stream()) break;
    // No ground truth: an empty labels packet.
    const LabelImage* labels = source.output_packet("labels").get_if<LabelImage>();
    frames.push_back({source.output<DepthImage>("depth"), labels ? *labels : LabelImage{}});
  }
  return frames;
}

bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::countNonZero(a != b) == 0;
}

// The bundled mOSD frames with their ground truth, recorded and read back: the same stems,
// depth, labels and intrinsics.
TEST(RecordSink, RecordingReplaysExactly) {
  const std::vector<Frame> original = read_all(data_dir() / "mosd");
  ASSERT_GE(original.size(), 2u);
  TempDir dir("facet-record");
  const auto recording = dir.path() / "recording";
  Recorder recorder({{"dir", ParamValue(recording.string())}});
  for (const Frame& frame : original) {
    recorder.set_input("depth", Packet::make(frame.depth));
    recorder.set_input("labels", Packet::make(frame.labels));
    recorder.run();
  }
  const std::vector<Frame> replayed = read_all(recording);
  ASSERT_EQ(replayed.size(), original.size());
  for (std::size_t i = 0; i < original.size(); ++i) {
    SCOPED_TRACE(original[i].depth.frame.stem);
    EXPECT_EQ(replayed[i].depth.frame.stem, original[i].depth.frame.stem);
    EXPECT_TRUE(same_pixels(replayed[i].depth.depth, original[i].depth.depth));
    EXPECT_TRUE(same_pixels(replayed[i].labels.labels, original[i].labels.labels));
    EXPECT_EQ(replayed[i].depth.camera.fx, original[i].depth.camera.fx);
    EXPECT_EQ(replayed[i].depth.camera.cy, original[i].depth.camera.cy);
    EXPECT_EQ(replayed[i].depth.camera.width, original[i].depth.camera.width);
  }
}

// Metric depth is written in millimetres (NaN as 0); without labels no label folder appears;
// a frame from another camera is refused, naming its file.
TEST(RecordSink, MetricDepthNoLabelsAndOneCamera) {
  TempDir dir("facet-record");
  const auto recording = dir.path() / "metric";
  DepthImage depth;
  depth.camera = {500.0, 501.0, 3.5, 2.5, 8, 6};
  depth.depth = cv::Mat(6, 8, CV_32FC1, cv::Scalar(1.2344F));
  depth.depth.at<float>(1, 2) = std::numeric_limits<float>::quiet_NaN();
  depth.frame.stem = "f0";
  Recorder recorder({{"dir", ParamValue(recording.string())}});
  recorder.set_input("depth", Packet::make(depth));
  recorder.run();
  const std::vector<Frame> replayed = read_all(recording);
  ASSERT_EQ(replayed.size(), 1u);
  EXPECT_EQ(replayed[0].depth.depth.at<std::uint16_t>(0, 0), 1234);
  EXPECT_EQ(replayed[0].depth.depth.at<std::uint16_t>(1, 2), 0);
  EXPECT_TRUE(replayed[0].labels.labels.empty());
  EXPECT_FALSE(std::filesystem::exists(recording / "label"));
  EXPECT_EQ(facet::io::read_intrinsics(recording / "intrinsics.yaml").fy, 501.0);

  depth.camera.fx = 520.0;
  depth.frame.stem = "f1";
  recorder.set_input("depth", Packet::make(depth));
  expect_stage_error([&] { recorder.run(); }, {"f1.png", "intrinsics"});
}

}  // namespace
