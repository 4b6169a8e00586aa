// io.pcd on PCD files written by the tests with PCL (from the bundled mOSD frames and small
// synthetic clouds). With FACET_REAL_DATA_DIR set to a folder holding mosd/pcd/*.pcd and the
// converted mosd/depth and mosd/label PNGs, it also checks the original mOSD clouds.
#ifdef FACET_HAVE_PCD

#include "pcd/pcd_source.hpp"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "pcd/cloud_images.hpp"
#include "stage_test_support.hpp"

namespace {

using facet::DepthImage;
using facet::LabelImage;
using facet::ParamValue;
using facet::pcd::PcdSource;
using facet::test::data_dir;
using facet::test::expect_stage_error;
using facet::test::TempDir;
using facet::test::write_text;
using Runner = facet::testing::StageRunner<PcdSource>;
using Cloud = pcl::PointCloud<pcl::PointXYZL>;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

cv::Mat read_png(const std::filesystem::path& file) {
  cv::Mat image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  EXPECT_FALSE(image.empty()) << file;
  return image;
}

// An organized cloud from a depth PNG (mm) and a label PNG, back-projected with the mOSD camera
// (fx = fy = 525, cx = 319.5, cy = 239.5), the label PNG's ids as the label field.
Cloud cloud_from_pngs(const cv::Mat& depth, const cv::Mat& labels) {
  Cloud cloud(static_cast<std::uint32_t>(depth.cols), static_cast<std::uint32_t>(depth.rows));
  cloud.is_dense = false;
  for (int v = 0; v < depth.rows; ++v) {
    for (int u = 0; u < depth.cols; ++u) {
      pcl::PointXYZL& point = cloud.at(u, v);
      const std::uint16_t mm = depth.at<std::uint16_t>(v, u);
      point.label = labels.at<std::uint16_t>(v, u);
      if (mm == 0) {
        point.x = point.y = point.z = kNaN;
        continue;
      }
      point.z = static_cast<float>(mm) / 1000.0F;
      point.x = static_cast<float>((u - 319.5) * point.z / 525.0);
      point.y = static_cast<float>((v - 239.5) * point.z / 525.0);
    }
  }
  return cloud;
}

void save(const std::filesystem::path& file, const Cloud& cloud) {
  std::filesystem::create_directories(file.parent_path());
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(file.string(), cloud), 0) << file;
}

// A 4x3 organized cloud at depth `mm` (all points valid), label = column + 1.
Cloud flat_cloud(float mm) {
  Cloud cloud(4, 3);
  for (int v = 0; v < 3; ++v) {
    for (int u = 0; u < 4; ++u) {
      pcl::PointXYZL& point = cloud.at(u, v);
      point.z = mm / 1000.0F;
      point.x = static_cast<float>((u - 1.5) * point.z / 100.0);
      point.y = static_cast<float>((v - 1.0) * point.z / 100.0);
      point.label = static_cast<std::uint32_t>(u + 1);
    }
  }
  return cloud;
}

TEST(PcdSource, OrganizedCloudGivesTheDepthAndLabelsItWasMadeFromAndFitsTheCamera) {
  TempDir dir;
  const cv::Mat depth = read_png(data_dir() / "mosd/depth/learn0.png");
  const cv::Mat labels = read_png(data_dir() / "mosd/label/learn0.png");
  save(dir / "learn0.pcd", cloud_from_pngs(depth, labels));

  Runner runner({{"path", dir.path().string()}});
  runner.run();
  ASSERT_FALSE(runner.at_end_of_stream());
  const auto& out = runner.output<DepthImage>("depth");
  EXPECT_EQ(out.frame.stem, "learn0");
  EXPECT_EQ(out.frame.index, 0);
  ASSERT_EQ(out.depth.type(), CV_16UC1);
  ASSERT_EQ(out.depth.size(), depth.size());
  EXPECT_EQ(cv::countNonZero(out.depth != depth), 0);
  EXPECT_NEAR(out.camera.fx, 525.0, 1e-3);
  EXPECT_NEAR(out.camera.fy, 525.0, 1e-3);
  EXPECT_NEAR(out.camera.cx, 319.5, 1e-3);
  EXPECT_NEAR(out.camera.cy, 239.5, 1e-3);
  EXPECT_EQ(out.camera.width, 640);
  EXPECT_EQ(out.camera.height, 480);

  const auto& gt = runner.output<LabelImage>("labels");
  ASSERT_EQ(gt.labels.type(), CV_32SC1);
  cv::Mat expected;
  labels.convertTo(expected, CV_32S);
  expected.setTo(0, depth == 0);
  EXPECT_EQ(cv::countNonZero(gt.labels != expected), 0);
  double max_label = 0.0;
  cv::minMaxLoc(expected, nullptr, &max_label);
  EXPECT_EQ(gt.count, static_cast<int>(max_label));

  bool has_fit_metric = false;
  for (const auto& metric : runner.metrics()) {
    if (metric.name == "fit_rms_px") {
      has_fit_metric = true;
      EXPECT_LT(metric.value, 0.01);
    }
  }
  EXPECT_TRUE(has_fit_metric);
  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());
}

TEST(PcdSource, GivenIntrinsicsAreUsedAsIs) {
  TempDir dir;
  save(dir / "a.pcd", flat_cloud(800.0F));
  Runner runner(
      {{"path", (dir / "a.pcd").string()}, {"fx", 90.0}, {"fy", 91.0}, {"cx", 1.0}, {"cy", 2.0}});
  runner.run();
  const auto& out = runner.output<DepthImage>("depth");
  EXPECT_DOUBLE_EQ(out.camera.fx, 90.0);
  EXPECT_DOUBLE_EQ(out.camera.cy, 2.0);
  EXPECT_EQ(out.camera.width, 4);
  EXPECT_EQ(out.camera.height, 3);
  EXPECT_EQ(cv::countNonZero(out.depth == 800), 12);
}

TEST(PcdSource, HalfGivenOrDoublyGivenIntrinsicsAreRefused) {
  TempDir dir;
  save(dir / "a.pcd", flat_cloud(800.0F));
  // One focal length without the other is refused when the stage is made, before any file.
  expect_stage_error(
      [&] {
        Runner({{"path", (dir / "a.pcd").string()}, {"fy", 91.0}});
      },
      {"fx and fy"});
  write_text(dir / "intrinsics.yaml", facet::test::intrinsics_yaml(4, 3));
  Runner both({{"path", (dir / "a.pcd").string()},
               {"intrinsics", (dir / "intrinsics.yaml").string()},
               {"fx", 90.0},
               {"fy", 91.0}});
  expect_stage_error([&] { both.run(); }, {"intrinsics", "not both"});
}

TEST(PcdSource, FolderAndGlobInNaturalOrderWithTimestampsAndStems) {
  TempDir dir;
  for (int n : {10, 2, 1})
    save(dir / ("c" + std::to_string(n) + ".pcd"), flat_cloud(100.0F * static_cast<float>(n)));
  write_text(dir / "notes.txt", "not a cloud");
  Runner runner({{"path", dir.path().string()}, {"fps", 10.0}});
  const std::vector<std::string> stems = {"c1", "c2", "c10"};
  for (std::size_t i = 0; i < stems.size(); ++i) {
    runner.run();
    ASSERT_FALSE(runner.at_end_of_stream());
    const auto& out = runner.output<DepthImage>("depth");
    EXPECT_EQ(out.frame.stem, stems[i]);
    EXPECT_EQ(out.frame.index, static_cast<std::int64_t>(i));
    EXPECT_EQ(out.frame.timestamp_ns, static_cast<std::int64_t>(i) * 100'000'000);
    EXPECT_EQ(out.depth.at<std::uint16_t>(0, 0), std::stoi(stems[i].substr(1)) * 100);
  }
  runner.run();
  EXPECT_TRUE(runner.at_end_of_stream());

  Runner glob({{"path", (dir / "c1*.pcd").string()}});
  glob.run();
  EXPECT_EQ(glob.output<DepthImage>("depth").frame.stem, "c1");
  glob.run();
  EXPECT_EQ(glob.output<DepthImage>("depth").frame.stem, "c10");
  glob.run();
  EXPECT_TRUE(glob.at_end_of_stream());
}

TEST(PcdSource, CloudWithoutLabelFieldHasNoLabels) {
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud(2, 2);
  for (auto& point : cloud) {
    point.z = 1.0F;
  }
  cloud.at(0, 0).x = -0.01F;
  cloud.at(1, 0).x = 0.01F;
  cloud.at(0, 1).x = -0.01F;
  cloud.at(1, 1).x = 0.01F;
  cloud.at(0, 0).y = cloud.at(1, 0).y = -0.01F;
  cloud.at(0, 1).y = cloud.at(1, 1).y = 0.01F;
  ASSERT_EQ(pcl::io::savePCDFileASCII((dir / "xyz.pcd").string(), cloud), 0);
  Runner runner({{"path", (dir / "xyz.pcd").string()}});
  runner.run();
  EXPECT_TRUE(runner.output_packet("labels").empty());
  const auto& out = runner.output<DepthImage>("depth");
  EXPECT_EQ(cv::countNonZero(out.depth == 1000), 4);
  EXPECT_NEAR(out.camera.fx, 50.0, 1e-3);
  EXPECT_NEAR(out.camera.cx, 0.5, 1e-3);
}

TEST(PcdSource, UnorganizedCloudIsReprojectedNearestPointWinning) {
  TempDir dir;
  Cloud cloud;
  // Two points on pixel (2, 1) of a 4x3 camera (fx = fy = 100, cx = 1.5, cy = 1), the nearer
  // one labelled 7; one on pixel (0, 0); one outside the image; one invalid.
  const auto add = [&cloud](double u, double v, float z, std::uint32_t label) {
    pcl::PointXYZL point;
    point.z = z;
    point.x = static_cast<float>((u - 1.5) * z / 100.0);
    point.y = static_cast<float>((v - 1.0) * z / 100.0);
    point.label = label;
    cloud.push_back(point);
  };
  add(2, 1, 0.9F, 3);
  add(2, 1, 0.6F, 7);
  add(0, 0, 1.2F, 5);
  add(40, 1, 1.0F, 9);
  add(1, 1, kNaN, 4);
  ASSERT_EQ(cloud.height, 1U);
  save(dir / "u.pcd", cloud);

  Runner runner({{"path", (dir / "u.pcd").string()},
                 {"fx", 100.0},
                 {"fy", 100.0},
                 {"cx", 1.5},
                 {"cy", 1.0},
                 {"width", std::int64_t{4}},
                 {"height", std::int64_t{3}}});
  runner.run();
  const auto& out = runner.output<DepthImage>("depth");
  ASSERT_EQ(out.depth.size(), cv::Size(4, 3));
  EXPECT_EQ(out.depth.at<std::uint16_t>(1, 2), 600);
  EXPECT_EQ(out.depth.at<std::uint16_t>(0, 0), 1200);
  EXPECT_EQ(cv::countNonZero(out.depth), 2);
  const auto& gt = runner.output<LabelImage>("labels");
  EXPECT_EQ(gt.labels.at<std::int32_t>(1, 2), 7);
  EXPECT_EQ(gt.labels.at<std::int32_t>(0, 0), 5);
  EXPECT_EQ(gt.count, 7);

  Runner refused({{"path", (dir / "u.pcd").string()}});
  expect_stage_error([&] { refused.run(); }, {"u.pcd", "unorganized", "intrinsics"});
}

TEST(PcdSource, BadFilesAreNamedWithWhatIsWrong) {
  TempDir dir;
  write_text(dir / "broken.pcd", "this is not a point cloud\n");
  Runner runner({{"path", (dir / "broken.pcd").string()}});
  expect_stage_error([&] { runner.run(); }, {"broken.pcd", "not a PCD header entry"});

  pcl::PointCloud<pcl::Normal> normals(2, 2);
  ASSERT_EQ(pcl::io::savePCDFileASCII((dir / "normals.pcd").string(), normals), 0);
  Runner no_xyz({{"path", (dir / "normals.pcd").string()}});
  expect_stage_error([&] { no_xyz.run(); }, {"normals.pcd", "'x'"});

  Runner missing({{"path", (dir / "none").string()}});
  expect_stage_error([&] { missing.run(); }, {"none", "does not exist"});

  TempDir empty;
  Runner no_files({{"path", empty.path().string()}});
  expect_stage_error([&] { no_files.run(); }, {"no .pcd files"});
}

TEST(PcdSource, SkipModeWarnsAndGoesOn) {
  TempDir dir;
  write_text(dir / "a1.pcd", "garbage");
  save(dir / "a2.pcd", flat_cloud(500.0F));
  Runner runner({{"path", dir.path().string()}, {"on_error", std::string("skip")}});
  runner.run();
  EXPECT_EQ(runner.output<DepthImage>("depth").frame.stem, "a2");
  ASSERT_EQ(runner.warnings().size(), 1U);
  EXPECT_NE(runner.warnings()[0].find("a1.pcd"), std::string::npos);
}

TEST(PcdSource, SizeMismatchWithGivenIntrinsicsIsAnError) {
  TempDir dir;
  save(dir / "a.pcd", flat_cloud(500.0F));
  write_text(dir / "intrinsics.yaml", facet::test::intrinsics_yaml(8, 6));
  Runner runner(
      {{"path", (dir / "a.pcd").string()}, {"intrinsics", (dir / "intrinsics.yaml").string()}});
  expect_stage_error([&] { runner.run(); }, {"a.pcd", "4x3", "8x6"});
}

TEST(PcdSource, CloudBehindTheCameraIsFlipped) {
  TempDir dir;
  Cloud cloud = flat_cloud(700.0F);
  for (auto& point : cloud) {
    point.y = -point.y;
    point.z = -point.z;
  }
  save(dir / "flipped.pcd", cloud);
  Runner runner({{"path", dir.path().string()}});
  runner.run();
  const auto& out = runner.output<DepthImage>("depth");
  EXPECT_EQ(cv::countNonZero(out.depth == 700), 12);
  EXPECT_NEAR(out.camera.fy, 100.0, 1e-3);
  ASSERT_EQ(runner.warnings().size(), 1U);
  EXPECT_NE(runner.warnings()[0].find("z < 0"), std::string::npos);
}

TEST(PcdLabelScheme, MosdObjectsAndParts) {
  const cv::Mat raw = (cv::Mat_<std::int32_t>(1, 8) << 0, 3, 20, 21, 40, 41, 9, 40);
  cv::Mat objects = raw.clone();
  EXPECT_EQ(facet::pcd::apply_label_scheme(objects, facet::pcd::LabelScheme::mosd), 2);
  EXPECT_EQ(cv::countNonZero(objects != (cv::Mat_<std::int32_t>(1, 8) << 0, 0, 1, 1, 2, 2, 0, 2)),
            0);
  cv::Mat parts = raw.clone();
  EXPECT_EQ(facet::pcd::apply_label_scheme(parts, facet::pcd::LabelScheme::mosd_parts), 4);
  EXPECT_EQ(cv::countNonZero(parts != (cv::Mat_<std::int32_t>(1, 8) << 0, 0, 1, 2, 3, 4, 0, 3)), 0);
}

// The original mOSD clouds against their converted PNGs (outside the repository: the clouds are
// not bundled). Set FACET_REAL_DATA_DIR to run it.
TEST(PcdSourceRealData, MosdCloudsMatchTheirDepthAndLabelPngs) {
  const char* root = std::getenv("FACET_REAL_DATA_DIR");
  if (root == nullptr) GTEST_SKIP() << "FACET_REAL_DATA_DIR not set";
  const std::filesystem::path mosd = std::filesystem::path(root) / "mosd";
  for (const char* scheme : {"mosd", "mosd_parts"}) {
    Runner runner({{"path", (mosd / "pcd").string()}, {"labels", std::string(scheme)}});
    int frames = 0;
    while (true) {
      runner.run();
      if (runner.at_end_of_stream()) break;
      ++frames;
      const auto& out = runner.output<DepthImage>("depth");
      SCOPED_TRACE(out.frame.stem);
      const cv::Mat depth = read_png(mosd / "depth" / (out.frame.stem + ".png"));
      cv::Mat difference;
      cv::absdiff(out.depth, depth, difference);
      double worst = 0.0;
      cv::minMaxLoc(difference, nullptr, &worst);
      EXPECT_LE(worst, 1.0);
      EXPECT_EQ(cv::countNonZero((out.depth == 0) != (depth == 0)), 0);
      EXPECT_NEAR(out.camera.fx, 525.0, 0.01);
      EXPECT_NEAR(out.camera.cy, 239.5, 0.01);
      const std::string folder = std::string(scheme) == "mosd" ? "label" : "label_parts";
      cv::Mat expected;
      read_png(mosd / folder / (out.frame.stem + ".png")).convertTo(expected, CV_32S);
      EXPECT_EQ(cv::countNonZero(runner.output<LabelImage>("labels").labels != expected), 0);
    }
    EXPECT_GE(frames, 1);
  }
}

}  // namespace

#endif  // FACET_HAVE_PCD
