// convert.points: back-projection round-trips through the pinhole model; invalid stays invalid.
#include <gtest/gtest.h>

#include <limits>

#include "convert/points_stage.hpp"
#include "normals_test_support.hpp"

namespace {

using facet::convert::PointsStage;
using namespace facet::test;

cv::Mat run_points(const facet::DepthImage& depth, const StageParams& params = {}) {
  facet::testing::StageRunner<PointsStage> runner(params);
  runner.set_input("depth", facet::Packet::make(depth));
  runner.run();
  const auto& out = runner.output<facet::PointImage>("points");
  EXPECT_EQ(out.camera.fx, depth.camera.fx);  // the header travels with the points
  return out.points.clone();
}

TEST(ConvertPoints, RoundTripsThroughThePinholeModel) {
  const auto frame = real_frame();
  const cv::Mat points = run_points(frame);
  ASSERT_EQ(points.type(), CV_32FC3);
  ASSERT_EQ(points.size(), frame.depth.size());
  const auto& cam = frame.camera;
  int valid = 0;
  for (int v = 0; v < points.rows; ++v) {
    for (int u = 0; u < points.cols; ++u) {
      const auto p = points.at<cv::Vec3f>(v, u);
      const auto mm = frame.depth.at<std::uint16_t>(v, u);
      if (mm == 0) {
        ASSERT_TRUE(std::isnan(p[0]) && std::isnan(p[1]) && std::isnan(p[2])) << u << "," << v;
        continue;
      }
      const double z = mm * 0.001;
      ASSERT_NEAR(p[2], z, 1e-6);
      ASSERT_NEAR(p[0], (u - cam.cx) * z / cam.fx, 1e-6);
      ASSERT_NEAR(p[1], (v - cam.cy) * z / cam.fy, 1e-6);
      // And back: the point projects onto its own pixel.
      ASSERT_NEAR(cam.fx * p[0] / p[2] + cam.cx, u, 1e-3);
      ASSERT_NEAR(cam.fy * p[1] / p[2] + cam.cy, v, 1e-3);
      ++valid;
    }
  }
  EXPECT_GT(valid, 100000);
}

TEST(ConvertPoints, FloatMetresAndNaNInput) {
  auto scene = SceneBuilder().plane({0.0, 0.0, 1.0}, tilted_normal(30.0, 0.0)).render();
  scene.depth_m.at<float>(10, 20) = std::numeric_limits<float>::quiet_NaN();
  scene.depth_m.at<float>(11, 20) = 0.0F;
  const cv::Mat points = run_points(scene.depth_m_image());
  EXPECT_TRUE(std::isnan(points.at<cv::Vec3f>(10, 20)[2]));
  EXPECT_TRUE(std::isnan(points.at<cv::Vec3f>(11, 20)[2]));
  EXPECT_FLOAT_EQ(points.at<cv::Vec3f>(100, 200)[2], scene.depth_m.at<float>(100, 200));
  // Points of the plane lie on it.
  const Eigen::Vector3d n = tilted_normal(30.0, 0.0);
  const double d = n.dot(Eigen::Vector3d(0.0, 0.0, 1.0));
  const auto p = points.at<cv::Vec3f>(300, 500);
  EXPECT_NEAR(n.dot(Eigen::Vector3d(p[0], p[1], p[2])), d, 1e-5);
}

TEST(ConvertPoints, DepthRangeMakesPointsInvalid) {
  auto depth = real_frame();
  const cv::Mat points = run_points(depth, {{"min_depth_m", 0.8}, {"max_depth_m", 1.0}});
  int kept = 0;
  for (int v = 0; v < points.rows; ++v) {
    for (int u = 0; u < points.cols; ++u) {
      const auto mm = depth.depth.at<std::uint16_t>(v, u);
      const bool in_range = mm >= 800 && mm <= 1000;
      ASSERT_EQ(!std::isnan(points.at<cv::Vec3f>(v, u)[2]), in_range) << mm;
      kept += in_range ? 1 : 0;
    }
  }
  EXPECT_GT(kept, 1000);
}

TEST(ConvertPoints, RefusesMissingIntrinsics) {
  auto depth = real_frame();
  depth.camera = {};
  EXPECT_THROW(run_points(depth), facet::StageError);
}

}  // namespace
