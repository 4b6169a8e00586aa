// io.overlay and io.cloud in the shipped graphs: tabletop_cloud.yaml on the bundled frames writes a
// picture and a point cloud per frame that agree with the label images of the same run.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_runner.hpp"

namespace facet::test {
namespace {

const std::filesystem::path kTabletop = source_dir() / "graphs/tabletop.yaml";
const std::filesystem::path kTabletopCloud = source_dir() / "graphs/tabletop_cloud.yaml";

struct Ply {
  std::int64_t vertices = -1;
  std::size_t header_bytes = 0;
  std::string bytes;
};

Ply read_ply_file(const std::filesystem::path& file) {
  Ply ply;
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  ply.bytes = buffer.str();
  const std::string end = "end_header\n";
  const auto at = ply.bytes.find(end);
  if (at == std::string::npos) return ply;
  ply.header_bytes = at + end.size();
  const std::string key = "\nelement vertex ";
  const auto count = ply.bytes.find(key);
  if (count != std::string::npos && count < at) {
    ply.vertices = std::stoll(ply.bytes.substr(count + key.size()));
  }
  return ply;
}

TEST(SinksRun, TabletopCloudWritesAnOverlayAndACloudPerFrame) {
  TempDir out("facet-run-sinks");
  const auto result = run_cli("run " + shell_quote(kTabletopCloud.string()) +
                              " -q --frames 2 --param output=" + shell_quote(out.path().string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;

  int frames = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out.path() / "labels")) {
    ++frames;
    const std::string stem = entry.path().stem().string();
    SCOPED_TRACE(stem);
    const cv::Mat labels = cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED);
    const cv::Mat depth = cv::imread((source_dir() / "data/mosd/depth" / (stem + ".png")).string(),
                                     cv::IMREAD_UNCHANGED);
    ASSERT_EQ(labels.type(), CV_16UC1);
    ASSERT_EQ(depth.type(), CV_16UC1);

    // The picture: colour where there are objects, grey elsewhere, black where depth is missing.
    const cv::Mat overlay =
        cv::imread((out.path() / "overlay" / (stem + ".png")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(overlay.type(), CV_8UC3);
    ASSERT_EQ(overlay.size(), labels.size());
    int coloured = 0;
    for (int y = 0; y < overlay.rows; ++y) {
      for (int x = 0; x < overlay.cols; ++x) {
        const cv::Vec3b p = overlay.at<cv::Vec3b>(y, x);
        const bool grey = p[0] == p[1] && p[1] == p[2];
        if (labels.at<std::uint16_t>(y, x) == 0) {
          ASSERT_TRUE(grey) << x << "," << y;
          if (depth.at<std::uint16_t>(y, x) == 0) {
            ASSERT_EQ(p, cv::Vec3b(0, 0, 0)) << x << "," << y;
          }
        } else if (!grey) {
          ++coloured;
        }
      }
    }
    EXPECT_GT(coloured, cv::countNonZero(labels) / 2);

    // The cloud: one vertex per valid depth pixel (median filter and back-projection keep every
    // measured pixel), each object's points with its id.
    const Ply ply = read_ply_file(out.path() / "cloud" / (stem + ".ply"));
    ASSERT_EQ(ply.vertices, cv::countNonZero(depth));
    ASSERT_EQ(ply.bytes.size(), ply.header_bytes + 19 * static_cast<std::size_t>(ply.vertices));
    std::map<std::uint32_t, int> cloud_ids;
    for (std::int64_t i = 0; i < ply.vertices; ++i) {
      std::uint32_t id = 0;
      std::memcpy(&id, ply.bytes.data() + ply.header_bytes + 19 * i + 15, 4);  // little-endian host
      ++cloud_ids[id];
    }
    std::map<std::uint32_t, int> image_ids;
    for (int y = 0; y < labels.rows; ++y) {
      for (int x = 0; x < labels.cols; ++x) {
        if (depth.at<std::uint16_t>(y, x) != 0) ++image_ids[labels.at<std::uint16_t>(y, x)];
      }
    }
    EXPECT_EQ(cloud_ids, image_ids);
  }
  EXPECT_EQ(frames, 2);
}

// tabletop_cloud.yaml extends tabletop.yaml by one node, so the two cannot drift apart: every
// variant of the base is one of the cloud graph's too.
TEST(SinksRun, TabletopCloudIsTabletopPlusTheCloudNode) {
  EXPECT_NE(read_file(kTabletopCloud).find("\nextends: tabletop.yaml\n"), std::string::npos);
  for (const char* variant : {"", "convex", "pca5", "pca_box"}) {
    const std::string option = *variant != 0 ? std::string(" --variant ") + variant : "";
    const auto result = run_cli("validate " + shell_quote(kTabletopCloud.string()) + option);
    EXPECT_EQ(result.exit_code, 0) << variant << "\n" << result.out;
  }
}

}  // namespace
}  // namespace facet::test
