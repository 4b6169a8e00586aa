// The PCD header check in front of PCL's reader: each mutated header below made PCL 1.13 crash,
// loop or allocate gigabytes; now each is refused with the file and the field named.
#ifdef FACET_HAVE_PCD

#include "pcd/pcd_header.hpp"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "pcd/pcd_source.hpp"
#include "stage_test_support.hpp"

namespace {

using facet::test::TempDir;
using facet::test::write_text;
using Runner = facet::testing::StageRunner<facet::pcd::PcdSource>;

// An 8x6 organized cloud at 0.5 m, written by PCL in `encoding`; returns the file's bytes.
std::string pcl_file(const std::filesystem::path& file, const std::string& encoding) {
  pcl::PointCloud<pcl::PointXYZL> cloud(8, 6);
  for (int v = 0; v < 6; ++v) {
    for (int u = 0; u < 8; ++u) {
      auto& point = cloud.at(u, v);
      point.z = 0.5F;
      point.x = static_cast<float>((u - 3.5) * 0.005);
      point.y = static_cast<float>((v - 2.5) * 0.005);
      point.label = static_cast<std::uint32_t>(u + 1);
    }
  }
  const std::string name = file.string();
  const int status = encoding == "ascii"    ? pcl::io::savePCDFileASCII(name, cloud)
                     : encoding == "binary" ? pcl::io::savePCDFileBinary(name, cloud)
                                            : pcl::io::savePCDFileBinaryCompressed(name, cloud);
  EXPECT_EQ(status, 0);
  std::ifstream stream(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

// `text` with its header line starting with `key` replaced by `line`.
std::string with_line(std::string text, const std::string& key, const std::string& line) {
  const std::size_t begin = text.find("\n" + key + " ") + 1;
  const std::size_t end = text.find('\n', begin);
  return text.replace(begin, end - begin, line);
}

// `text` (binary_compressed) with the uncompressed size in front of the data set to `bytes`.
std::string with_uncompressed_size(std::string text, std::uint32_t bytes) {
  const std::size_t data = text.find("DATA binary_compressed\n") + 23;
  std::memcpy(text.data() + data + 4, &bytes, 4);
  return text;
}

// Reads `text` as a PCD file through io.pcd and checks the error names the file and `parts`.
void expect_refused(const std::string& text, std::initializer_list<std::string_view> parts) {
  TempDir dir;
  write_text(dir / "mutated.pcd", text);
  Runner runner({{"path", (dir / "mutated.pcd").string()}});
  try {
    runner.run();
    ADD_FAILURE() << "expected facet::StageError";
  } catch (const facet::StageError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("mutated.pcd"), std::string::npos) << message;
    for (const std::string_view part : parts)
      EXPECT_NE(message.find(part), std::string::npos) << message << "\n lacks: " << part;
  }
}

class PcdHeaderCheck : public ::testing::Test {
 protected:
  TempDir dir_;
  std::string compressed_ = pcl_file(dir_ / "c.pcd", "binary_compressed");
  std::string binary_ = pcl_file(dir_ / "b.pcd", "binary");
  std::string ascii_ = pcl_file(dir_ / "a.pcd", "ascii");
};

TEST_F(PcdHeaderCheck, FilesWrittenByPclPassInEveryEncoding) {
  for (const char* name : {"c.pcd", "b.pcd", "a.pcd"}) {
    const auto header = facet::pcd::check_pcd_file(dir_ / name);
    EXPECT_EQ(header.points, 48U) << name;
    EXPECT_EQ(header.width, 8U) << name;
    EXPECT_EQ(header.point_bytes(), 16U) << name;
    Runner runner({{"path", (dir_ / name).string()}});
    runner.run();
    EXPECT_EQ(runner.output<facet::DepthImage>("depth").depth.at<std::uint16_t>(1, 1), 500) << name;
  }
}

TEST_F(PcdHeaderCheck, CountsAndSizesThatAreNotPositiveAreRefused) {
  expect_refused(with_line(compressed_, "COUNT", "COUNT -1 1 1 1"),
                 {"line 6", "COUNT of field 'x' '-1'"});
  expect_refused(with_line(compressed_, "COUNT", "COUNT 1 1 1 1 -1"), {"COUNT has 5 entries"});
  expect_refused(with_line(compressed_, "COUNT", "COUNT 1 1 1 0"), {"field 'label' '0'"});
  expect_refused(with_line(compressed_, "SIZE", "SIZE -1 4 4 4"), {"SIZE '-1' of field 'x'"});
  expect_refused(with_line(compressed_, "SIZE", "SIZE 2 4 4 4"), {"float", "SIZE 2"});
  expect_refused(with_line(compressed_, "TYPE", "TYPE F F F X"), {"TYPE 'X'"});
}

TEST_F(PcdHeaderCheck, DeclaredDataMustFitTheFile) {
  // A larger COUNT than the data was written with: the data no longer matches.
  expect_refused(with_line(compressed_, "COUNT", "COUNT 1 1 1 2"),
                 {"uncompressed size 768", "48 points of 20 bytes"});
  expect_refused(with_line(binary_, "COUNT", "COUNT 1 1 1 2"), {"960 bytes of binary data"});
  expect_refused(with_uncompressed_size(compressed_, 0), {"uncompressed size 0"});
  expect_refused(with_uncompressed_size(compressed_, 0xfffffff0U), {"uncompressed size"});
  // More points than the file holds, consistent with WIDTH and HEIGHT or not.
  auto more = with_line(with_line(binary_, "WIDTH", "WIDTH 1000"), "POINTS", "POINTS 6000");
  expect_refused(more, {"6000 points of 16 bytes"});
  more = with_line(with_line(ascii_, "WIDTH", "WIDTH 1000"), "POINTS", "POINTS 6000");
  expect_refused(more, {"ascii data"});
  expect_refused(with_line(compressed_, "POINTS", "POINTS 99999999"),
                 {"'99999999' is not an integer from 1 to 67108864"});
  expect_refused(with_line(compressed_, "POINTS", "POINTS 11"), {"8 x 6 is not POINTS 11"});
}

TEST_F(PcdHeaderCheck, WhatIsNoPcdHeaderIsRefused) {
  expect_refused("this is not a point cloud\n", {"line 1", "'this' is not a PCD header entry"});
  expect_refused(with_line(compressed_, "DATA", "DATA zipped"), {"DATA 'zipped'"});
  expect_refused(compressed_.substr(0, 60), {"without a DATA line"});
  const std::size_t data = compressed_.find("DATA binary_compressed\n") + 23;
  expect_refused(compressed_.substr(0, data + 5), {"ends before the sizes"});
  auto twice = with_line(compressed_, "VERSION", "WIDTH 4");
  expect_refused(twice, {"a second WIDTH line"});
}

// A cloud read with the wrong WIDTH and HEIGHT (16x3 for 8x6) has a consistent header, but its
// points no longer project onto the grid: refused, not read into a scrambled image.
TEST_F(PcdHeaderCheck, AReshapedCloudIsRefusedByItsIntrinsicsFit) {
  const auto reshaped =
      with_line(with_line(compressed_, "WIDTH", "WIDTH 16"), "HEIGHT", "HEIGHT 3");
  expect_refused(reshaped, {"do not project onto its 16x3 grid", "max_fit_rms_px"});

  TempDir dir;
  write_text(dir / "reshaped.pcd", reshaped);
  Runner lenient({{"path", (dir / "reshaped.pcd").string()}, {"max_fit_rms_px", 1000.0}});
  lenient.run();
  EXPECT_EQ(lenient.output<facet::DepthImage>("depth").depth.cols, 16);
}

}  // namespace

#endif  // FACET_HAVE_PCD
