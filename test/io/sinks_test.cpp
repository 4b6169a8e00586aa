// io.depth and io.labels: what they write reads back identically, also through io.frames.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "io/depth_sink.hpp"
#include "io/edges_sink.hpp"
#include "io/frames_source.hpp"
#include "io/labels_sink.hpp"
#include "stage_test_support.hpp"

namespace {

using facet::DepthImage;
using facet::LabelImage;
using facet::Packet;
using facet::test::expect_stage_error;
using facet::test::intrinsics_yaml;
using facet::test::TempDir;
using facet::test::write_text;

facet::FrameHeader header(const std::string& stem, std::int64_t index = 0) {
  facet::FrameHeader h;
  h.frame.stem = stem;
  h.frame.index = index;
  return h;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

cv::Mat read_unchanged(const std::filesystem::path& file) {
  return cv::imread(file.string(), cv::IMREAD_UNCHANGED);
}

bool equal(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::countNonZero(a != b) == 0;
}

cv::Mat random_depth_mm(int width, int height) {
  cv::Mat depth(height, width, CV_16UC1);
  cv::RNG rng(7);
  rng.fill(depth, cv::RNG::UNIFORM, 0, 65536);
  return depth;
}

TEST(DepthSink, MillimetresRoundTripIntoANewNestedFolder) {
  TempDir dir;
  const auto out = dir / "a/b/depth";
  facet::testing::StageRunner<facet::io::DepthSink> sink({{"dir", out.string()}});
  const cv::Mat depth = random_depth_mm(31, 17);
  sink.set_input("depth", Packet::make(DepthImage{header("learn7"), depth}));
  sink.run();
  EXPECT_TRUE(equal(read_unchanged(out / "learn7.png"), depth));
}

TEST(DepthSink, MetresAreRoundedAndInvalidBecomesZero) {
  TempDir dir;
  facet::testing::StageRunner<facet::io::DepthSink> sink({{"dir", dir.path().string()}});
  cv::Mat metres(1, 5, CV_32FC1);
  metres.at<float>(0, 0) = 0.5004F;
  metres.at<float>(0, 1) = 1.2346F;
  metres.at<float>(0, 2) = std::numeric_limits<float>::quiet_NaN();
  metres.at<float>(0, 3) = 70.0F;  // does not fit 16-bit millimetres
  metres.at<float>(0, 4) = -1.0F;
  sink.set_input("depth", Packet::make(DepthImage{header("", 42), metres}));
  sink.run();
  const cv::Mat written = read_unchanged(dir / "frame_000042.png");
  ASSERT_EQ(written.type(), CV_16UC1);
  EXPECT_EQ(written.at<std::uint16_t>(0, 0), 500);
  EXPECT_EQ(written.at<std::uint16_t>(0, 1), 1235);
  EXPECT_EQ(written.at<std::uint16_t>(0, 2), 0);
  EXPECT_EQ(written.at<std::uint16_t>(0, 3), 0);
  EXPECT_EQ(written.at<std::uint16_t>(0, 4), 0);
  ASSERT_EQ(sink.warnings().size(), 1U);
  EXPECT_NE(sink.warnings()[0].find("65.535 m"), std::string::npos);
}

TEST(LabelsSink, WritesUint16AndSkipsEmptyPackets) {
  TempDir dir;
  facet::testing::StageRunner<facet::io::LabelsSink> sink({{"dir", (dir / "labels").string()}});
  cv::Mat labels(4, 6, CV_32SC1, cv::Scalar(0));
  labels.at<std::int32_t>(1, 2) = 65535;
  labels.at<std::int32_t>(3, 5) = 3;
  sink.set_input("labels", Packet::make(LabelImage{header("scene"), labels, 65535}));
  sink.run();
  const cv::Mat written = read_unchanged(dir / "labels/scene.png");
  ASSERT_EQ(written.type(), CV_16UC1);
  cv::Mat back;
  written.convertTo(back, CV_32S);
  EXPECT_TRUE(equal(back, labels));

  sink.set_input("labels", Packet{});
  sink.run();
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir / "labels"),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(LabelsSink, RejectsIdsA16BitPngCannotHold) {
  TempDir dir;
  facet::testing::StageRunner<facet::io::LabelsSink> sink({{"dir", dir.path().string()}});
  cv::Mat labels(2, 2, CV_32SC1, cv::Scalar(1));
  labels.at<std::int32_t>(0, 1) = 65536;
  sink.set_input("labels", Packet::make(LabelImage{header("big"), labels, 65536}));
  expect_stage_error([&] { sink.run(); }, {"big.png", "65536", "65535"});
  EXPECT_FALSE(std::filesystem::exists(dir / "big.png"));

  // Negative ids break LabelImage's format and never reach a sink.
  labels.at<std::int32_t>(0, 1) = -2;
  EXPECT_THROW(sink.set_input("labels", Packet::make(LabelImage{header("neg"), labels, 1})),
               std::invalid_argument);
}

// A symlink in the output folder made a sink overwrite the link's target. Results are written
// to a temporary file and renamed: the link is replaced, its target kept, nothing left over.
TEST(LabelsSink, WritesNeverFollowASymlinkAndLeaveNoPartialFiles) {
  TempDir dir;
  write_text(dir / "precious.txt", "keep me");
  std::filesystem::create_directories(dir / "labels");
  std::filesystem::create_symlink(dir / "precious.txt", dir / "labels/scene.png");
  facet::testing::StageRunner<facet::io::LabelsSink> sink({{"dir", (dir / "labels").string()}});
  sink.set_input("labels", Packet::make(LabelImage{header("scene"),
                                                   cv::Mat(2, 3, CV_32SC1, cv::Scalar(4)), 4}));
  sink.run();
  EXPECT_EQ(read_text(dir / "precious.txt"), "keep me");
  EXPECT_FALSE(std::filesystem::is_symlink(dir / "labels/scene.png"));
  EXPECT_EQ(read_unchanged(dir / "labels/scene.png").at<std::uint16_t>(1, 2), 4);
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "labels"))
    names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"scene.png"});
}

// A write that fails (here: the folder is gone) names the file and leaves nothing behind.
TEST(LabelsSink, AFailedWriteNamesTheFile) {
  TempDir dir;
  facet::testing::StageRunner<facet::io::LabelsSink> sink({{"dir", (dir / "labels").string()}});
  sink.set_input("labels", Packet::make(LabelImage{header("gone"),
                                                   cv::Mat(2, 3, CV_32SC1, cv::Scalar(1)), 1}));
  sink.run();
  std::filesystem::remove_all(dir / "labels");
  sink.set_input("labels", Packet::make(LabelImage{header("gone"),
                                                   cv::Mat(2, 3, CV_32SC1, cv::Scalar(1)), 1}));
  expect_stage_error([&] { sink.run(); }, {"gone.png", "No such file"});
}

// A run into a folder of earlier results leaves the files of frames it does not write: the sink
// says so once, on its first frame, with the folder and how many files it held.
TEST(LabelsSink, SaysOnceThatTheFolderAlreadyHeldResults) {
  TempDir dir;
  std::filesystem::create_directories(dir / "labels");
  write_text(dir / "labels/old1.png", "x");
  write_text(dir / "labels/old2.png", "x");
  write_text(dir / "labels/notes.txt", "not a result of this sink");
  write_text(dir / "labels/.old3.png.partial-7", "an interrupted write");
  facet::testing::StageRunner<facet::io::LabelsSink> sink({{"dir", (dir / "labels").string()}});
  const auto frame = [](const std::string& stem) {
    return Packet::make(LabelImage{header(stem), cv::Mat(2, 3, CV_32SC1, cv::Scalar(1)), 1});
  };
  sink.set_input("labels", frame("a"));
  sink.run();
  ASSERT_EQ(sink.warnings().size(), 1u);
  EXPECT_NE(sink.warnings()[0].find((dir / "labels").string()), std::string::npos);
  EXPECT_NE(sink.warnings()[0].find("already held 2 .png file"), std::string::npos);
  sink.set_input("labels", frame("b"));
  sink.run();
  EXPECT_TRUE(sink.warnings().empty());
}

TEST(LabelsSink, AFreshFolderGivesNoWarning) {
  TempDir dir;
  facet::testing::StageRunner<facet::io::LabelsSink> sink({{"dir", (dir / "labels").string()}});
  sink.set_input("labels",
                 Packet::make(LabelImage{header("a"), cv::Mat(2, 3, CV_32SC1, cv::Scalar(1)), 1}));
  sink.run();
  EXPECT_TRUE(sink.warnings().empty());
}

TEST(LabelsSink, FolderThatCannotBeCreatedIsAnOpenError) {
  TempDir dir;
  write_text(dir / "occupied", "a file, not a folder");
  facet::testing::StageRunner<facet::io::LabelsSink> sink({{"dir", (dir / "occupied").string()}});
  sink.set_input("labels", Packet{});
  expect_stage_error([&] { sink.run(); }, {"occupied"});
}

// What the sinks write is a dataset that io.frames reads back unchanged.
TEST(SinksAndSource, WrittenDatasetReadsBackThroughIoFrames) {
  TempDir dir;
  write_text(dir / "intrinsics.yaml", intrinsics_yaml(31, 17));
  const cv::Mat depth = random_depth_mm(31, 17);
  cv::Mat labels(17, 31, CV_32SC1, cv::Scalar(0));
  labels(cv::Rect(3, 4, 10, 5)).setTo(1);
  labels(cv::Rect(20, 2, 5, 9)).setTo(2);
  {
    facet::testing::StageRunner<facet::io::DepthSink> depth_sink(
        {{"dir", (dir / "depth").string()}});
    facet::testing::StageRunner<facet::io::LabelsSink> label_sink(
        {{"dir", (dir / "label").string()}});
    depth_sink.set_input("depth", Packet::make(DepthImage{header("x"), depth}));
    label_sink.set_input("labels", Packet::make(LabelImage{header("x"), labels, 2}));
    depth_sink.run();
    label_sink.run();
  }
  facet::testing::StageRunner<facet::io::FramesSource> source({{"path", dir.path().string()}});
  source.run();
  EXPECT_TRUE(equal(source.output<DepthImage>("depth").depth, depth));
  EXPECT_TRUE(equal(source.output<LabelImage>("labels").labels, labels));
  EXPECT_EQ(source.output<LabelImage>("labels").count, 2);
}

}  // namespace

namespace {

facet::EdgeImage edge_image(const std::string& stem) {
  facet::EdgeImage edges;
  edges.frame.stem = stem;
  edges.score =
      (cv::Mat_<float>(1, 4) << 0.0f, 0.5f, 1.0f, std::numeric_limits<float>::quiet_NaN());
  edges.mask = (cv::Mat_<std::uint8_t>(1, 4) << 255, 255, 0, 255);
  return edges;
}

TEST(EdgesSink, WritesTheMaskAs8Bit) {
  TempDir dir;
  facet::testing::StageRunner<facet::io::EdgesSink> sink({{"dir", (dir / "edges").string()}});
  sink.set_input("edges", Packet::make(edge_image("scene")));
  sink.run();
  const cv::Mat written = read_unchanged(dir / "edges/scene.png");
  ASSERT_EQ(written.type(), CV_8UC1);
  EXPECT_TRUE(equal(written, edge_image("scene").mask));
}

TEST(EdgesSink, WritesTheScoreScaledWithNaNAsZero) {
  TempDir dir;
  facet::testing::StageRunner<facet::io::EdgesSink> sink(
      {{"dir", dir.path().string()}, {"what", std::string("score")}});
  sink.set_input("edges", Packet::make(edge_image("s")));
  sink.run();
  const cv::Mat written = read_unchanged(dir / "s.png");
  ASSERT_EQ(written.type(), CV_8UC1);
  EXPECT_EQ(written.at<std::uint8_t>(0, 0), 0);
  EXPECT_EQ(written.at<std::uint8_t>(0, 1), 128);
  EXPECT_EQ(written.at<std::uint8_t>(0, 2), 255);
  EXPECT_EQ(written.at<std::uint8_t>(0, 3), 0);
}

TEST(EdgesSink, AnEdgeImageWithoutAMaskNeverReachesIt) {
  TempDir dir;
  facet::testing::StageRunner<facet::io::EdgesSink> sink({{"dir", dir.path().string()}});
  facet::EdgeImage edges = edge_image("m");
  edges.mask = cv::Mat();
  try {
    sink.set_input("edges", Packet::make(edges));
    FAIL() << "an edge image without a mask was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "input 'edges' (facet.EdgeImage/1): mask is empty");
  }
}

}  // namespace
