// io.frames on the bundled frames and on small datasets written by the tests.
#include "io/frames_source.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "stage_test_support.hpp"

namespace {

using facet::DepthImage;
using facet::LabelImage;
using facet::ParamValue;
using facet::io::FramesSource;
using facet::test::data_dir;
using facet::test::depth_mm;
using facet::test::expect_stage_error;
using facet::test::intrinsics_yaml;
using facet::test::TempDir;
using facet::test::write_png;
using facet::test::write_text;
using Runner = facet::testing::StageRunner<FramesSource>;

constexpr int kWidth = 8;
constexpr int kHeight = 6;

// Runs the source to the end of the stream; returns the stems it emitted.
std::vector<std::string> read_all_stems(Runner& runner, int max_frames = 100) {
  std::vector<std::string> stems;
  for (int i = 0; i < max_frames; ++i) {
    runner.run();
    if (runner.at_end_of_stream()) break;
    stems.push_back(runner.output<DepthImage>("depth").frame.stem);
  }
  return stems;
}

// A dataset folder with 8x6 frames f1, f2, f10 (depth = 100 * number); labels for f2 only.
class TinyDataset : public ::testing::Test {
 protected:
  void SetUp() override {
    write_text(dir_ / "intrinsics.yaml", intrinsics_yaml(kWidth, kHeight));
    for (int n : {10, 2, 1}) {
      write_png(dir_ / ("depth/f" + std::to_string(n) + ".png"),
                depth_mm(kWidth, kHeight, static_cast<std::uint16_t>(100 * n)));
    }
    cv::Mat labels(kHeight, kWidth, CV_16UC1, cv::Scalar(0));
    labels(cv::Rect(0, 0, 3, 3)).setTo(1);
    labels(cv::Rect(4, 2, 2, 2)).setTo(2);
    write_png(dir_ / "label/f2.png", labels);
  }

  std::string path() const { return dir_.path().string(); }
  std::filesystem::path file(const std::string& name) const { return dir_ / name; }

  TempDir dir_;
};

TEST(FramesSourceBundled, ReadsMosdInNaturalOrderWithLabelsAndEnds) {
  Runner runner({{"path", (data_dir() / "mosd").string()}});
  const std::vector<std::string> expected = {"learn0",  "learn5",  "learn18",
                                             "learn20", "learn27", "learn36"};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    runner.run();
    ASSERT_FALSE(runner.at_end_of_stream()) << "frame " << i;
    const auto& depth = runner.output<DepthImage>("depth");
    EXPECT_EQ(depth.frame.stem, expected[i]);
    EXPECT_EQ(depth.frame.index, static_cast<std::int64_t>(i));
    EXPECT_EQ(depth.depth.type(), CV_16UC1);
    EXPECT_EQ(depth.depth.size(), cv::Size(640, 480));
    EXPECT_DOUBLE_EQ(depth.camera.fx, 525.0);
    EXPECT_DOUBLE_EQ(depth.camera.cy, 239.5);
    const auto& labels = runner.output<LabelImage>("labels");
    EXPECT_EQ(labels.labels.type(), CV_32SC1);
    EXPECT_EQ(labels.frame.stem, expected[i]);
    EXPECT_GE(labels.count, 2);

    ASSERT_EQ(runner.metrics().size(), 1U);
    EXPECT_EQ(runner.metrics()[0].name, "valid_ratio");
    const double valid = cv::countNonZero(depth.depth) / 307200.0;
    EXPECT_DOUBLE_EQ(runner.metrics()[0].value, valid);
    EXPECT_GT(valid, 0.3);  // mOSD keeps table and objects: 160k-210k of 307k pixels
  }
  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());
}

TEST(FramesSourceBundled, TimestampsFollowTheNominalFrameRate) {
  Runner runner({{"path", (data_dir() / "mosd").string()}, {"fps", 10.0}});
  runner.run();
  EXPECT_EQ(runner.output<DepthImage>("depth").frame.timestamp_ns, 0);
  runner.run();
  EXPECT_EQ(runner.output<DepthImage>("depth").frame.timestamp_ns, 100'000'000);
}

TEST(FramesSourceBundled, LabelsDirSelectsPartLevelGroundTruth) {
  Runner objects({{"path", (data_dir() / "mosd").string()}, {"start", std::int64_t{5}}});
  Runner parts({{"path", (data_dir() / "mosd").string()},
                {"start", std::int64_t{5}},
                {"labels_dir", std::string("label_parts")}});
  objects.run();
  parts.run();
  ASSERT_EQ(objects.output<DepthImage>("depth").frame.stem, "learn36");
  EXPECT_EQ(objects.output<LabelImage>("labels").count, 3);  // 3 cylinders
  EXPECT_EQ(parts.output<LabelImage>("labels").count, 8);    // split into 8 parts by occlusion
}

TEST(FramesSourceBundled, GlobSelectsFilesAndFindsIntrinsicsInTheDatasetFolder) {
  Runner runner({{"path", (data_dir() / "mosd/depth/learn2*.png").string()}});
  EXPECT_EQ(read_all_stems(runner), (std::vector<std::string>{"learn20", "learn27"}));
}

TEST(FramesSourceBundled, ReadsYcbVideo) {
  Runner runner({{"path", (data_dir() / "ycb_video").string()}});
  runner.run();
  const auto& depth = runner.output<DepthImage>("depth");
  EXPECT_EQ(depth.frame.stem, "000001");
  EXPECT_NEAR(depth.camera.fx, 1066.778, 1e-9);
  EXPECT_EQ(runner.output<LabelImage>("labels").count, 3);
}

TEST_F(TinyDataset, NaturalOrderAndGroundTruthOnlyWhereThereIsAFile) {
  Runner runner({{"path", path()}});
  const std::vector<std::string> expected = {"f1", "f2", "f10"};
  for (const std::string& stem : expected) {
    runner.run();
    ASSERT_FALSE(runner.at_end_of_stream());
    const auto& depth = runner.output<DepthImage>("depth");
    EXPECT_EQ(depth.frame.stem, stem);
    EXPECT_EQ(depth.depth.at<std::uint16_t>(0, 0), 100 * std::stoi(stem.substr(1)));
    const bool has_labels = !runner.output_packet("labels").empty();
    EXPECT_EQ(has_labels, stem == "f2") << stem;
    if (has_labels) {
      const auto& labels = runner.output<LabelImage>("labels");
      EXPECT_EQ(labels.count, 2);
      EXPECT_EQ(labels.labels.at<std::int32_t>(1, 1), 1);
      EXPECT_EQ(labels.labels.at<std::int32_t>(3, 5), 2);
    }
  }
  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());
}

TEST_F(TinyDataset, WithoutLabelFolderEveryLabelPacketIsEmpty) {
  std::filesystem::remove_all(file("label"));
  Runner runner({{"path", path()}});
  for (int i = 0; i < 3; ++i) {
    runner.run();
    EXPECT_TRUE(runner.output_packet("labels").empty());
    EXPECT_FALSE(runner.output_packet("depth").empty());
  }
}

TEST_F(TinyDataset, StartStrideAndLoop) {
  Runner strided({{"path", path()}, {"start", std::int64_t{1}}, {"stride", std::int64_t{2}}});
  EXPECT_EQ(read_all_stems(strided), (std::vector<std::string>{"f2"}));

  Runner looping({{"path", path()}, {"start", std::int64_t{1}}, {"loop", true}});
  EXPECT_EQ(read_all_stems(looping, 5), (std::vector<std::string>{"f2", "f10", "f2", "f10", "f2"}));
  EXPECT_EQ(looping.output<DepthImage>("depth").frame.index, 4);
}

TEST_F(TinyDataset, StartBeyondTheLastFrameIsAnOpenError) {
  Runner runner({{"path", path()}, {"start", std::int64_t{3}}});
  expect_stage_error([&] { runner.run(); }, {"start=3", "only 3 frames"});
}

TEST_F(TinyDataset, EightBitDepthIsAnErrorNamingTheFile) {
  write_png(file("depth/f2.png"), cv::Mat(kHeight, kWidth, CV_8UC1, cv::Scalar(7)));
  Runner runner({{"path", path()}});
  runner.run();
  expect_stage_error([&] { runner.run(); }, {"f2.png", "8-bit"});
}

TEST_F(TinyDataset, WrongSizeIsAnErrorNamingBothSizes) {
  write_png(file("depth/f1.png"), depth_mm(4, 3, 100));
  Runner runner({{"path", path()}});
  expect_stage_error([&] { runner.run(); }, {"f1.png", "4x3", "8x6"});
}

TEST_F(TinyDataset, LabelOfWrongSizeIsAnError) {
  write_png(file("label/f2.png"), cv::Mat(3, 4, CV_16UC1, cv::Scalar(1)));
  Runner runner({{"path", path()}});
  runner.run();
  expect_stage_error([&] { runner.run(); }, {"label", "f2.png", "4x3"});
}

TEST_F(TinyDataset, CorruptPngIsAnErrorNamingTheFile) {
  write_text(file("depth/f2.png"), std::string("\x89PNG\r\n\x1a\n", 8) + "not really a png");
  Runner runner({{"path", path()}});
  runner.run();
  expect_stage_error([&] { runner.run(); }, {"f2.png", "cannot read"});
}

TEST_F(TinyDataset, SkipModeWarnsNamingTheFileAndGoesOn) {
  write_text(file("depth/f2.png"), "garbage");
  write_png(file("depth/f10.png"), cv::Mat(kHeight, kWidth, CV_8UC1, cv::Scalar(7)));
  write_png(file("depth/f11.png"), depth_mm(kWidth, kHeight, 1100));
  Runner runner({{"path", path()}, {"on_error", std::string("skip")}});

  runner.run();
  EXPECT_EQ(runner.output<DepthImage>("depth").frame.stem, "f1");
  EXPECT_TRUE(runner.warnings().empty());

  runner.run();  // f2 and f10 are skipped within one call
  const auto& depth = runner.output<DepthImage>("depth");
  EXPECT_EQ(depth.frame.stem, "f11");
  EXPECT_EQ(depth.frame.index, 1);  // position in the stream, not in the folder
  ASSERT_EQ(runner.warnings().size(), 2U);
  EXPECT_NE(runner.warnings()[0].find("f2.png"), std::string::npos) << runner.warnings()[0];
  EXPECT_NE(runner.warnings()[1].find("f10.png"), std::string::npos) << runner.warnings()[1];
  EXPECT_NE(runner.warnings()[1].find("8-bit"), std::string::npos) << runner.warnings()[1];

  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());
}

// A frame without a single valid pixel is read like any other (later stages find nothing in it),
// with a warning naming the file.
TEST_F(TinyDataset, FrameWithoutValidDepthWarnsNamingTheFile) {
  write_png(file("depth/f2.png"), depth_mm(kWidth, kHeight, 0));
  Runner runner({{"path", path()}});
  runner.run();
  EXPECT_TRUE(runner.warnings().empty());
  runner.run();
  EXPECT_EQ(runner.output<DepthImage>("depth").frame.stem, "f2");
  ASSERT_EQ(runner.warnings().size(), 1U);
  EXPECT_NE(runner.warnings()[0].find("no valid depth"), std::string::npos) << runner.warnings()[0];
  EXPECT_NE(runner.warnings()[0].find("f2.png"), std::string::npos) << runner.warnings()[0];
  runner.run();
  EXPECT_TRUE(runner.warnings().empty());
}

TEST_F(TinyDataset, SkipModeEndsALoopWhereEveryFrameIsBad) {
  for (const char* stem : {"f1", "f2", "f10"})
    write_text(file(std::string("depth/") + stem + ".png"), "x");
  Runner runner({{"path", path()}, {"on_error", std::string("skip")}, {"loop", true}});
  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());
  EXPECT_EQ(runner.warnings().size(), 3U);
}

TEST_F(TinyDataset, MissingIntrinsicsKeyNamesFileAndKey) {
  write_text(file("intrinsics.yaml"), "fx: 500\ncx: 4\ncy: 3\nwidth: 8\nheight: 6\n");
  Runner runner({{"path", path()}});
  expect_stage_error([&] { runner.run(); }, {"intrinsics.yaml", "'fy'"});
}

TEST_F(TinyDataset, NonNumericIntrinsicsValueNamesLineAndKey) {
  write_text(file("intrinsics.yaml"),
             "# camera\nfx: 500\nfy: five hundred\ncx: 4\ncy: 3\nwidth: 8\nheight: 6\n");
  Runner runner({{"path", path()}});
  expect_stage_error([&] { runner.run(); }, {"intrinsics.yaml:3:", "'fy'", "five hundred"});
}

// Values that parse but cannot be a camera ran without error and gave no objects; each is
// refused naming its line and key.
TEST_F(TinyDataset, ImplausibleIntrinsicsValuesAreRefusedNamingLineAndKey) {
  const std::string rest = "\ncx: 4\ncy: 3\nwidth: 8\nheight: 6\n";
  for (const std::string fx : {".inf", "1e300", "1e-300", ".nan", "-500", "0"}) {
    write_text(file("intrinsics.yaml"), "# camera\nfx: " + fx + "\nfy: 500" + rest);
    Runner runner({{"path", path()}});
    expect_stage_error([&] { runner.run(); }, {"intrinsics.yaml:2:", "'fx'", "focal length"});
  }
  for (const std::string cx : {".nan", ".inf", "-1e9"}) {
    write_text(file("intrinsics.yaml"),
               "fx: 500\nfy: 500\ncx: " + cx + "\ncy: 3\nwidth: 8\nheight: 6\n");
    Runner runner({{"path", path()}});
    expect_stage_error([&] { runner.run(); }, {"intrinsics.yaml:3:", "'cx'", "principal point"});
  }
  write_text(file("intrinsics.yaml"), "fx: 500\nfy: 500\ncx: 4\ncy: 3\nwidth: 8\nheight: 0\n");
  Runner no_height({{"path", path()}});
  expect_stage_error([&] { no_height.run(); }, {"intrinsics.yaml:6:", "'height'"});
}

TEST_F(TinyDataset, AKeySaidTwiceInTheIntrinsicsIsRefused) {
  write_text(file("intrinsics.yaml"),
             "fx: 500\nfy: 500\ncx: 4\ncy: 3\nwidth: 8\nheight: 6\nfx: 50\n");
  Runner runner({{"path", path()}});
  expect_stage_error([&] { runner.run(); }, {"intrinsics.yaml:7:", "'fx' appears twice"});
}

TEST_F(TinyDataset, MissingIntrinsicsFileIsAnOpenError) {
  std::filesystem::remove(file("intrinsics.yaml"));
  Runner runner({{"path", path()}});
  expect_stage_error([&] { runner.run(); }, {"intrinsics.yaml", "not found"});
}

TEST_F(TinyDataset, ExplicitIntrinsicsFileWithAGlob) {
  std::filesystem::rename(file("intrinsics.yaml"), file("camera.yaml"));
  Runner runner({{"path", (dir_.path() / "depth/f1*.png").string()},
                 {"intrinsics", file("camera.yaml").string()}});
  EXPECT_EQ(read_all_stems(runner), (std::vector<std::string>{"f1", "f10"}));
}

TEST(FramesSourceOpen, MissingFolderAndEmptyFolderAreErrors) {
  TempDir dir;
  Runner missing({{"path", (dir / "nowhere").string()}});
  expect_stage_error([&] { missing.run(); }, {"nowhere", "does not exist"});

  std::filesystem::create_directories(dir / "depth");
  Runner empty({{"path", dir.path().string()}});
  expect_stage_error([&] { empty.run(); }, {"no frames", "depth"});

  Runner no_match({{"path", (dir / "depth/*.png").string()}});
  expect_stage_error([&] { no_match.run(); }, {"matches no files"});
}

}  // namespace
