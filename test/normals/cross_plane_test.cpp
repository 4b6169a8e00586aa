// normals.cross on exact ray-cast planes and boxes: the true normal in metric space, the
// analytic normal of the plane in image space.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "normals/cross_stage.hpp"
#include "normals_test_support.hpp"

namespace {

using facet::normals::CrossStage;
using namespace facet::test;

struct Errors {
  double max_deg = 0.0;
  double median_deg = 0.0;
  int count = 0;
};

// Angle errors at every pixel with a normal, against `expected(u, v)`.
template <class Expected>
Errors errors_against(const cv::Mat& normals, Expected expected) {
  std::vector<double> errors;
  for (int v = 0; v < normals.rows; ++v) {
    for (int u = 0; u < normals.cols; ++u) {
      if (!has_normal(normals, v, u)) continue;
      errors.push_back(angle_deg(normal_at(normals, v, u), expected(u, v)));
    }
  }
  Errors result;
  result.count = static_cast<int>(errors.size());
  if (errors.empty()) return result;
  std::sort(errors.begin(), errors.end());
  result.max_deg = errors.back();
  result.median_deg = errors[errors.size() / 2];
  return result;
}

// A steeply tilted plane runs off to tens of metres; keep what a depth sensor would measure.
RenderedScene sensor_range(RenderedScene scene) {
  scene.depth_m.setTo(0.0F, scene.depth_m > 3.0F);
  return scene;
}

class CrossPlaneTilt : public ::testing::TestWithParam<std::tuple<double, const char*>> {};

TEST_P(CrossPlaneTilt, MetricNormalIsTheTrueNormal) {
  const auto [tilt_deg, triangle] = GetParam();
  const Eigen::Vector3d n = tilted_normal(tilt_deg, 30.0);
  const auto scene = sensor_range(SceneBuilder().plane({0.0, 0.0, 1.2}, n).render());
  const cv::Mat normals = run_normals<CrossStage>(
      scene.depth_m_image(),
      {{"space", std::string("metric")}, {"triangle", std::string(triangle)}});
  const Errors e = errors_against(normals, [&](int, int) { return n; });
  EXPECT_GT(e.count, 10000) << "tilt " << tilt_deg;
  EXPECT_LT(e.max_deg, 1.0) << "tilt " << tilt_deg;
}

TEST_P(CrossPlaneTilt, MetricNormalFromMillimetresIsCloseOnAverage) {
  const auto [tilt_deg, triangle] = GetParam();
  const Eigen::Vector3d n = tilted_normal(tilt_deg, 30.0);
  const auto scene = sensor_range(SceneBuilder().plane({0.0, 0.0, 1.2}, n).render());
  const cv::Mat normals = run_normals<CrossStage>(
      scene.depth_mm_image(),
      {{"space", std::string("metric")}, {"triangle", std::string(triangle)}});
  // 1 mm steps over a 4-pixel (about 9 mm) baseline: single normals scatter, their median
  // error stays small and no normal flips.
  const Errors e = errors_against(normals, [&](int, int) { return n; });
  EXPECT_GT(e.count, 10000);
  EXPECT_LT(e.median_deg, 6.0) << "tilt " << tilt_deg;
  EXPECT_LT(e.max_deg, 60.0) << "tilt " << tilt_deg;
}

TEST_P(CrossPlaneTilt, DisparitySpaceNormalIsThePlanesNormalThere) {
  const auto [tilt_deg, triangle] = GetParam();
  const Eigen::Vector3d n = tilted_normal(tilt_deg, 30.0);
  const Eigen::Vector3d p0(0.0, 0.0, 1.2);
  const auto scene = sensor_range(SceneBuilder().plane(p0, n).render());
  const double depth_scale = 1.5;
  const cv::Mat normals =
      run_normals<CrossStage>(scene.depth_m_image(), {{"space", std::string("image")},
                                                      {"image_depth", std::string("disparity")},
                                                      {"depth_scale", depth_scale},
                                                      {"triangle", std::string(triangle)}});
  const PlaneView plane{n, n.dot(p0), scene.camera};
  // Raw disparity is affine in 1 / depth, so a 3D plane is a plane in this space too, with one
  // normal everywhere; 640 px wide doubles the unit (width / 320).
  const Eigen::Vector3d expected = plane.disparity_space_normal(depth_scale * 2.0);
  const Errors e = errors_against(normals, [&](int, int) { return expected; });
  EXPECT_GT(e.count, 10000);
  EXPECT_LT(e.max_deg, 0.5) << "tilt " << tilt_deg;
}

TEST_P(CrossPlaneTilt, MillimetreSpaceNormalFollowsTheDepthGradient) {
  const auto [tilt_deg, triangle] = GetParam();
  const Eigen::Vector3d n = tilted_normal(tilt_deg, 30.0);
  const Eigen::Vector3d p0(0.0, 0.0, 1.2);
  const auto scene = sensor_range(SceneBuilder().plane(p0, n).render());
  const cv::Mat normals =
      run_normals<CrossStage>(scene.depth_m_image(), {{"space", std::string("image")},
                                                      {"image_depth", std::string("mm")},
                                                      {"triangle", std::string(triangle)}});
  const PlaneView plane{n, n.dot(p0), scene.camera};
  // In (px, px, mm) the plane is slightly curved; the finite difference over 2r pixels matches
  // the gradient at the pixel up to that curvature.
  const Errors e =
      errors_against(normals, [&](int u, int v) { return plane.mm_space_normal(u, v); });
  EXPECT_GT(e.count, 10000);
  EXPECT_LT(e.median_deg, 0.2) << "tilt " << tilt_deg;
  EXPECT_LT(e.max_deg, 1.0) << "tilt " << tilt_deg;
}

INSTANTIATE_TEST_SUITE_P(Tilts, CrossPlaneTilt,
                         ::testing::Combine(::testing::Values(0.0, 10.0, 30.0, 50.0, 70.0),
                                            ::testing::Values("paper", "centred")));

TEST(CrossStage, BoxFacesGiveTheirFaceNormals) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  pose.linear() = (Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  const auto scene = SceneBuilder().box(pose, {0.15, 0.1, 0.12}).render();
  const cv::Mat normals =
      run_normals<CrossStage>(scene.depth_m_image(), {{"space", std::string("metric")}});
  const int r = 2;
  std::map<int, int> checked_per_face;
  for (int v = r; v < normals.rows - r; ++v) {
    for (int u = r; u < normals.cols - r; ++u) {
      const int face = scene.face.at<int>(v, u);
      if (face == 0) continue;
      // Only pixels whose whole neighbourhood lies on the same face.
      bool same_face = true;
      for (int dv = -r; dv <= r && same_face; ++dv) {
        for (int du = -r; du <= r; ++du)
          same_face &= scene.face.at<int>(v + dv, u + du) == face;
      }
      if (!same_face) continue;
      ASSERT_TRUE(has_normal(normals, v, u)) << u << "," << v;
      const int local = face - 1;  // the box is the first primitive: faces 1..6
      Eigen::Vector3d axis = Eigen::Vector3d::Zero();
      axis[local / 2] = local % 2 == 0 ? -1.0 : 1.0;
      const Eigen::Vector3d expected = pose.linear() * axis;
      EXPECT_LT(angle_deg(normal_at(normals, v, u), expected), 1.0) << "face " << local;
      ++checked_per_face[local];
    }
  }
  // Three faces of the rotated box are visible, each over many pixels.
  ASSERT_EQ(checked_per_face.size(), 3U);
  for (const auto& [face, count] : checked_per_face)
    EXPECT_GT(count, 500) << "face " << face;
}

TEST(CrossStage, MetricNormalsFaceTheCamera) {
  const auto scene = SceneBuilder().plane({0.1, -0.1, 1.5}, tilted_normal(60.0, 200.0)).render();
  for (const char* space : {"metric", "image"}) {
    const cv::Mat normals =
        run_normals<CrossStage>(scene.depth_mm_image(), {{"space", std::string(space)}});
    int checked = 0;
    int not_unit = 0;
    int facing_away = 0;
    for (int v = 0; v < normals.rows; ++v) {
      for (int u = 0; u < normals.cols; ++u) {
        if (!has_normal(normals, v, u)) continue;
        const Eigen::Vector3d n = normal_at(normals, v, u);
        not_unit += std::abs(n.norm() - 1.0) > 1e-5 ? 1 : 0;
        const double z = scene.depth_m.at<float>(v, u);
        const Eigen::Vector3d p((u - 319.5) * z / 525.0, (v - 239.5) * z / 525.0, z);
        const double facing = std::string(space) == "metric" ? n.dot(p) : n.z();
        facing_away += facing >= 0.0 ? 1 : 0;
        ++checked;
      }
    }
    EXPECT_GT(checked, 100000) << space;
    EXPECT_EQ(not_unit, 0) << space;
    EXPECT_EQ(facing_away, 0) << space;
  }
}

}  // namespace
