// io.frames on the flat (NNNNNN-depth.png) and TUM RGB-D layouts, with small datasets written by
// the tests.
#include <gtest/gtest.h>

#include <string>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "io/frames_source.hpp"
#include "stage_test_support.hpp"

namespace {

using facet::DepthImage;
using facet::LabelImage;
using facet::io::FramesSource;
using facet::test::depth_mm;
using facet::test::expect_stage_error;
using facet::test::intrinsics_yaml;
using facet::test::TempDir;
using facet::test::write_png;
using facet::test::write_text;
using Runner = facet::testing::StageRunner<FramesSource>;

constexpr int kWidth = 8;
constexpr int kHeight = 6;

TEST(FlatLayout, ReadsNumberedDepthAndLabelFilesInOrder) {
  TempDir dir;
  write_text(dir / "intrinsics.yaml", intrinsics_yaml(kWidth, kHeight));
  for (int n : {10, 2, 0}) {
    const std::string stem = "0000" + std::string(n < 10 ? "0" : "") + std::to_string(n);
    write_png(dir / (stem + "-depth.png"), depth_mm(kWidth, kHeight, std::uint16_t(100 + n)));
    write_png(dir / (stem + "-color.png"), cv::Mat(kHeight, kWidth, CV_8UC3, cv::Scalar(1)));
  }
  cv::Mat labels(kHeight, kWidth, CV_8UC1, cv::Scalar(0));
  labels(cv::Rect(1, 1, 2, 2)).setTo(3);
  write_png(dir / "000002-label.png", labels);

  for (const std::string& path : {dir.path().string(), (dir / "*-depth.png").string()}) {
    SCOPED_TRACE(path);
    Runner runner({{"path", path}});
    const std::vector<std::string> stems = {"000000", "000002", "000010"};
    for (const std::string& stem : stems) {
      runner.run();
      ASSERT_FALSE(runner.at_end_of_stream());
      const auto& depth = runner.output<DepthImage>("depth");
      EXPECT_EQ(depth.frame.stem, stem);
      EXPECT_EQ(depth.depth.at<std::uint16_t>(0, 0), 100 + std::stoi(stem));
      EXPECT_EQ(runner.output_packet("labels").empty(), stem != "000002");
      if (stem == "000002") {
        const auto& gt = runner.output<LabelImage>("labels");
        EXPECT_EQ(gt.count, 3);
        EXPECT_EQ(gt.labels.at<std::int32_t>(1, 1), 3);
      }
    }
    runner.run();
    EXPECT_TRUE(runner.at_end_of_stream());
  }

  Runner no_labels({{"path", dir.path().string()}, {"labels_dir", std::string()}});
  no_labels.run();
  no_labels.run();
  EXPECT_TRUE(no_labels.output_packet("labels").empty());
}

// A TUM RGB-D sequence: depth.txt and associations.txt, depth PNGs in units of 1/5000 m.
class TumDataset : public ::testing::Test {
 protected:
  void SetUp() override {
    write_text(dir_ / "intrinsics.yaml", intrinsics_yaml(kWidth, kHeight));
    write_png(dir_ / "depth/1305031102.160407.png", depth_mm(kWidth, kHeight, 5000));
    write_png(dir_ / "depth/1305031102.194330.png", depth_mm(kWidth, kHeight, 7503));
    write_text(dir_ / "depth.txt",
               "# depth maps\n# file: 'rgbd_dataset_freiburg1_xyz.bag'\n# timestamp filename\n"
               "1305031102.160407 depth/1305031102.160407.png\n"
               "1305031102.194330 depth/1305031102.194330.png\n");
  }
  TempDir dir_;
};

TEST_F(TumDataset, DepthListGivesTimestampsAndMillimetres) {
  Runner runner({{"path", dir_.path().string()}});
  runner.run();
  const auto& first = runner.output<DepthImage>("depth");
  EXPECT_EQ(first.frame.stem, "1305031102.160407");
  EXPECT_EQ(first.frame.timestamp_ns, 1305031102160407000);
  EXPECT_EQ(first.depth.at<std::uint16_t>(0, 0), 1000);
  runner.run();
  const auto& second = runner.output<DepthImage>("depth");
  EXPECT_EQ(second.frame.index, 1);
  EXPECT_EQ(second.frame.timestamp_ns, 1305031102194330000);
  EXPECT_EQ(second.depth.at<std::uint16_t>(0, 0), 1501);  // 7503 / 5 = 1500.6
  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());
}

TEST_F(TumDataset, AssociationsArePreferredAndTheDepthColumnIsFound) {
  write_text(dir_ / "associations.txt",
             "1305031102.175304 rgb/1305031102.175304.png 1305031102.194330 "
             "depth/1305031102.194330.png\n");
  Runner runner({{"path", dir_.path().string()}});
  runner.run();
  EXPECT_EQ(runner.output<DepthImage>("depth").frame.timestamp_ns, 1305031102194330000);
  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());

  // The list file itself, and an explicit scale.
  Runner list({{"path", (dir_ / "depth.txt").string()}, {"depth_scale", 1000.0}});
  list.run();
  EXPECT_EQ(list.output<DepthImage>("depth").depth.at<std::uint16_t>(0, 0), 5000);
}

TEST_F(TumDataset, MalformedListsNameFileAndLine) {
  write_text(dir_ / "bad.txt", "# ok\n1305031102.1 depth/a.png extra\n");
  Runner runner({{"path", (dir_ / "bad.txt").string()}});
  expect_stage_error([&] { runner.run(); }, {"bad.txt:2", "fields"});
  write_text(dir_ / "bad.txt", "yesterday depth/a.png\n");
  Runner stamp({{"path", (dir_ / "bad.txt").string()}});
  expect_stage_error([&] { stamp.run(); }, {"bad.txt:1", "timestamp"});
}

// Point clouds and OpenNI2 recordings are read by other source stages: io.frames names the stage
// and how to run it, for one file, a folder of them and a glob, rather than "not a folder".
TEST(OtherSources, APcdFileFolderOrGlobNamesIoPcd) {
  TempDir dir;
  write_text(dir / "clouds" / "a.pcd", "# .PCD v0.7\n");
  write_text(dir / "clouds" / "b.PCD", "# .PCD v0.7\n");
  for (const std::string& path : {(dir / "clouds" / "a.pcd").string(), (dir / "clouds").string(),
                                  (dir / "clouds" / "*").string()}) {
    Runner runner({{"path", path}});
    expect_stage_error(
        [&] { runner.run(); },
        {"'" + path + "'", "PCD point cloud", "io.frames does not read", "io.pcd", "facet_pcd",
         "`--replace source=io.pcd --set source.path='" + path + "'`", "docs/data-formats.md"});
  }
}

TEST(OtherSources, AnOniFileNamesIoOpenni2AndTheLiveGraph) {
  TempDir dir;
  write_text(dir / "take.oni", "not really a recording");
  const std::string file = (dir / "take.oni").string();
  Runner runner({{"path", file}});
  expect_stage_error([&] { runner.run(); },
                     {"'" + file + "' is an OpenNI2 recording", "io.openni2",
                      "facet run graphs/live.yaml --param uri=" + file, "docs/cameras.md"});
  Runner folder({{"path", dir.path().string()}});
  expect_stage_error([&] { folder.run(); },
                     {"holds OpenNI2 recordings", "io.openni2", "uri=<one of them>.oni"});
}

TEST(OtherSources, OtherFilesKeepTheDatasetErrors) {
  TempDir dir;
  write_text(dir / "notes.md", "nothing to read");
  Runner file({{"path", (dir / "notes.md").string()}});
  expect_stage_error([&] { file.run(); }, {"is not a folder", "TUM list"});
  Runner folder({{"path", dir.path().string()}});
  expect_stage_error([&] { folder.run(); }, {"has no depth/ folder"});
  // A folder with PNG frames and a stray cloud beside them is still a dataset.
  write_text(dir / "intrinsics.yaml", intrinsics_yaml(kWidth, kHeight));
  write_png(dir / "depth" / "f0.png", depth_mm(kWidth, kHeight, 800));
  write_text(dir / "scan.pcd", "# .PCD v0.7\n");
  Runner dataset({{"path", dir.path().string()}});
  dataset.run();
  EXPECT_EQ(dataset.output<DepthImage>("depth").frame.stem, "f0");
}

}  // namespace
