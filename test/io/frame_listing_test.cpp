// Finding frames: the flat and TUM RGB-D layouts, TUM timestamps and depth scales.
#include "io/frame_listing.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "stage_test_support.hpp"

namespace {

using facet::io::FrameLayout;
using facet::io::list_frames;
using facet::test::expect_stage_error;
using facet::test::TempDir;
using facet::test::write_text;

TEST(FrameListing, FlatFolderPairsDepthAndLabelByFrameName) {
  TempDir dir;
  for (const char* name : {"000010-depth.png", "000002-depth.png", "000002-color.png",
                           "000002-label.png", "notes.txt"}) {
    write_text(dir / name, "x");
  }
  for (const std::string& path : {dir.path().string(), (dir / "*-depth.png").string()}) {
    SCOPED_TRACE(path);
    const auto listing = list_frames(path);
    EXPECT_EQ(listing.layout, FrameLayout::flat);
    EXPECT_EQ(listing.root, dir.path());
    ASSERT_EQ(listing.depth_files.size(), 2U);
    EXPECT_EQ(listing.depth_files[0], dir / "000002-depth.png");
    EXPECT_EQ(listing.stems, (std::vector<std::string>{"000002", "000010"}));
    ASSERT_EQ(listing.label_files.size(), 2U);
    EXPECT_EQ(listing.label_files[0], dir / "000002-label.png");
    EXPECT_EQ(listing.label_files[1], dir / "000010-label.png");
    EXPECT_TRUE(listing.timestamps_ns.empty());
    EXPECT_DOUBLE_EQ(listing.depth_units_per_metre, 1000.0);
  }
}

TEST(FrameListing, DatasetFolderKeepsItsLayout) {
  TempDir dir;
  write_text(dir / "depth/learn10.png", "x");
  write_text(dir / "depth/learn2.png", "x");
  const auto listing = list_frames(dir.path().string());
  EXPECT_EQ(listing.layout, FrameLayout::dataset);
  EXPECT_EQ(listing.stems, (std::vector<std::string>{"learn2", "learn10"}));
  EXPECT_TRUE(listing.label_files.empty());
}

TEST(FrameListing, TumListsGiveTimestampsInListOrderAndTheTumScale) {
  TempDir dir;
  write_text(dir / "depth.txt",
             "# depth maps\n# timestamp filename\n"
             "1305031102.194330 depth/1305031102.194330.png\n"
             "1305031102.160407 depth/1305031102.160407.png  # comment\n\n");
  auto listing = list_frames(dir.path().string());
  EXPECT_EQ(listing.layout, FrameLayout::tum);
  ASSERT_EQ(listing.depth_files.size(), 2U);
  EXPECT_EQ(listing.depth_files[0], dir / "depth/1305031102.194330.png");
  EXPECT_EQ(listing.stems[1], "1305031102.160407");
  EXPECT_EQ(listing.timestamps_ns,
            (std::vector<std::int64_t>{1305031102194330000, 1305031102160407000}));
  EXPECT_DOUBLE_EQ(listing.depth_units_per_metre, 5000.0);

  // associations.txt is preferred; the depth pair is found in either column order.
  write_text(dir / "associations.txt",
             "1.5 rgb/a.png 2.25 depth/b.png\n3 depth/c.png 3.1 rgb/c.png\n");
  listing = list_frames(dir.path().string());
  EXPECT_EQ(listing.timestamps_ns, (std::vector<std::int64_t>{2250000000, 3000000000}));
  EXPECT_EQ(listing.stems, (std::vector<std::string>{"b", "c"}));

  listing = list_frames((dir / "depth.txt").string());
  EXPECT_EQ(listing.depth_files.size(), 2U);
  EXPECT_EQ(listing.root, dir.path());
}

TEST(FrameListing, MalformedTumListsNameFileAndLine) {
  TempDir dir;
  write_text(dir / "a.txt", "# ok\n1.0 rgb/a.png 2.0 rgb/b.png\n");
  expect_stage_error([&] { list_frames((dir / "a.txt").string()); }, {"a.txt:2", "depth"});
  write_text(dir / "b.txt", "1.0\n");
  expect_stage_error([&] { list_frames((dir / "b.txt").string()); }, {"b.txt:1", "1 fields"});
  write_text(dir / "c.txt", "# nothing\n");
  expect_stage_error([&] { list_frames((dir / "c.txt").string()); }, {"c.txt", "no depth"});
  TempDir empty;
  expect_stage_error([&] { list_frames(empty.path().string()); },
                     {"no depth/ folder", "-depth.png", "depth.txt"});
}

TEST(FrameListing, ParsesSecondsExactlyAndConvertsDepthScales) {
  std::int64_t ns = 0;
  ASSERT_TRUE(facet::io::parse_seconds("1305031102.175304", ns));
  EXPECT_EQ(ns, 1305031102175304000);
  ASSERT_TRUE(facet::io::parse_seconds("12", ns));
  EXPECT_EQ(ns, 12'000'000'000);
  EXPECT_FALSE(facet::io::parse_seconds("1.2e3", ns));
  EXPECT_FALSE(facet::io::parse_seconds("", ns));
  EXPECT_FALSE(facet::io::parse_seconds("-1.5", ns));
  // Found by the TUM list fuzz target: ten digits of seconds overflowed 64-bit nanoseconds.
  EXPECT_FALSE(facet::io::parse_seconds("9305031102.160407", ns));
  ASSERT_TRUE(facet::io::parse_seconds("9223372036.854775807", ns));
  EXPECT_EQ(ns, std::numeric_limits<std::int64_t>::max());
  EXPECT_FALSE(facet::io::parse_seconds("9223372036.854775808", ns));

  const cv::Mat tenth_mm = (cv::Mat_<std::uint16_t>(1, 3) << 0, 6005, 65535);
  const cv::Mat mm = facet::io::depth_to_millimetres(tenth_mm, 10000.0);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 0), 0);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 1), 601);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 2), 6554);
  const cv::Mat far = (cv::Mat_<std::uint16_t>(1, 1) << 65535);
  EXPECT_EQ(facet::io::depth_to_millimetres(far, 500.0).at<std::uint16_t>(0, 0), 0);
}

}  // namespace
