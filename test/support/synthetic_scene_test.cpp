#include "synthetic_scene.hpp"

#include <gtest/gtest.h>

#include <set>

namespace facet::test {
namespace {

TEST(SyntheticScene, FrontoParallelPlaneHasConstantDepth) {
  const auto scene = SceneBuilder().plane({0, 0, 1.2}, {0, 0, -1}).render();
  double lo = 0, hi = 0;
  cv::minMaxLoc(scene.depth_m, &lo, &hi);
  EXPECT_NEAR(lo, 1.2, 1e-6);
  EXPECT_NEAR(hi, 1.2, 1e-6);
  EXPECT_EQ(scene.depth_mm_image().depth.at<std::uint16_t>(240, 320), 1200);
}

TEST(SyntheticScene, TiltedPlaneDepthFollowsThePlaneEquation) {
  // Plane through (0,0,1) with normal (0, -sin a, -cos a): depth grows towards the image top.
  const double a = 30.0 * M_PI / 180.0;
  const auto scene = SceneBuilder().plane({0, 0, 1.0}, {0, -std::sin(a), -std::cos(a)}).render();
  const auto camera = scene.camera;
  for (int v : {60, 240, 420}) {
    const double y = (v - camera.cy) / camera.fy;
    const double expected = 1.0 / (1.0 + y * std::tan(a));  // n·(X - P) = 0 solved for Z
    EXPECT_NEAR(scene.depth_m.at<float>(v, 320), expected, 1e-5) << v;
  }
}

TEST(SyntheticScene, BoxSeenFromAnAngleShowsThreeFaces) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Eigen::Vector3d(0, 0, 1.0));
  pose.rotate(Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitY()));
  pose.rotate(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()));
  const auto scene = SceneBuilder().box(pose, {0.1, 0.1, 0.1}).render();
  std::set<int> faces;
  for (int v = 0; v < scene.face.rows; ++v) {
    for (int u = 0; u < scene.face.cols; ++u) {
      if (scene.face.at<int>(v, u) != 0) faces.insert(scene.face.at<int>(v, u));
    }
  }
  EXPECT_EQ(faces.size(), 3u);
}

TEST(SyntheticScene, CylinderSideIsNearerThanItsAxis) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Eigen::Vector3d(0, 0, 1.0));
  pose.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));  // axis along image y
  const auto scene = SceneBuilder().cylinder(pose, 0.05, 0.1).render();
  EXPECT_NEAR(scene.depth_m.at<float>(240, 320), 0.95f, 1e-4);  // front of the side
  EXPECT_EQ(scene.object.at<int>(240, 320), 1);
  EXPECT_EQ(scene.object.at<int>(0, 0), 0);
}

}  // namespace
}  // namespace facet::test
