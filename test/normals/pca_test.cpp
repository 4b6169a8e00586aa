// normals.pca: true normals on planes, agreement with normals.cross, which pixels get one.
#include <gtest/gtest.h>

#include "normals/cross_stage.hpp"
#include "normals/pca_stage.hpp"
#include "normals_test_support.hpp"

namespace {

using facet::normals::CrossStage;
using facet::normals::PcaStage;
using namespace facet::test;

RenderedScene sensor_range(RenderedScene scene) {
  scene.depth_m.setTo(0.0F, scene.depth_m > 3.0F);
  return scene;
}

class PcaPlane : public ::testing::TestWithParam<std::tuple<double, std::int64_t>> {};

TEST_P(PcaPlane, MetricNormalIsTheTrueNormal) {
  const auto [tilt_deg, window] = GetParam();
  const Eigen::Vector3d n = tilted_normal(tilt_deg, -60.0);
  const auto scene = sensor_range(SceneBuilder().plane({0.0, 0.0, 1.1}, n).render());
  const cv::Mat normals = run_normals<PcaStage>(
      scene.depth_m_image(), {{"space", std::string("metric")}, {"window", window}});
  int checked = 0;
  double worst = 0.0;
  for (int v = 0; v < normals.rows; ++v) {
    for (int u = 0; u < normals.cols; ++u) {
      if (!has_normal(normals, v, u)) continue;
      worst = std::max(worst, angle_deg(normal_at(normals, v, u), n));
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000);
  EXPECT_LT(worst, 1.0) << "tilt " << tilt_deg;
}

// On a plane both methods estimate the same normal: exactly the plane's in disparity space
// (where a 3D plane stays a plane) and in metric space.
TEST_P(PcaPlane, AgreesWithCrossProductOnPlanes) {
  const auto [tilt_deg, window] = GetParam();
  const auto scene =
      sensor_range(SceneBuilder().plane({0.0, 0.0, 1.1}, tilted_normal(tilt_deg, 45.0)).render());
  for (const char* space : {"image", "metric"}) {
    const StageParams common{{"space", std::string(space)}};
    StageParams pca = common;
    pca["window"] = window;
    const cv::Mat a = run_normals<PcaStage>(scene.depth_m_image(), pca);
    const cv::Mat b = run_normals<CrossStage>(scene.depth_m_image(), common);
    int compared = 0;
    double worst = 0.0;
    for (int v = 0; v < a.rows; ++v) {
      for (int u = 0; u < a.cols; ++u) {
        if (!has_normal(a, v, u) || !has_normal(b, v, u)) continue;
        worst = std::max(worst, angle_deg(normal_at(a, v, u), normal_at(b, v, u)));
        ++compared;
      }
    }
    EXPECT_GT(compared, 10000) << space;
    EXPECT_LT(worst, 0.5) << space << " tilt " << tilt_deg;
  }
}

INSTANTIATE_TEST_SUITE_P(TiltsAndWindows, PcaPlane,
                         ::testing::Combine(::testing::Values(0.0, 20.0, 45.0, 70.0),
                                            ::testing::Values(std::int64_t{3}, std::int64_t{5},
                                                              std::int64_t{7})));

// A pixel has a normal exactly when it is valid, its window is inside the image, and enough of
// the window is valid.
TEST(PcaStage, NormalExactlyWhereTheWindowHasEnoughValidPoints) {
  auto scene = SceneBuilder().plane({0.0, 0.0, 1.0}, tilted_normal(20.0, 10.0)).render();
  // A checkerboard of holes, so that windows see every count of valid points.
  for (int v = 100; v < 200; ++v) {
    for (int u = 100; u < 300; ++u) {
      if ((u * 7 + v * 13) % 5 < 2) scene.depth_m.at<float>(v, u) = 0.0F;
    }
  }
  scene.depth_m(cv::Rect(400, 300, 40, 30)).setTo(0.0F);
  for (const std::int64_t window : {3, 5}) {
    for (const double fraction : {0.0, 0.5, 1.0}) {
      const cv::Mat normals = run_normals<PcaStage>(
          scene.depth_mm_image(),
          {{"window", window}, {"min_valid_fraction", fraction}, {"space", std::string("metric")}});
      const int h = static_cast<int>(window / 2);
      const int needed =
          std::max(3, static_cast<int>(std::ceil(fraction * static_cast<double>(window * window))));
      int wrong = 0;
      for (int v = 0; v < normals.rows; ++v) {
        for (int u = 0; u < normals.cols; ++u) {
          bool expected = u >= h && v >= h && u < normals.cols - h && v < normals.rows - h &&
                          scene.depth_m.at<float>(v, u) > 0.0F;
          if (expected) {
            int valid = 0;
            for (int dv = -h; dv <= h; ++dv) {
              for (int du = -h; du <= h; ++du)
                valid += scene.depth_m.at<float>(v + dv, u + du) > 0.0F;
            }
            expected = valid >= needed;
          }
          wrong += has_normal(normals, v, u) != expected ? 1 : 0;
        }
      }
      EXPECT_EQ(wrong, 0) << "window " << window << " fraction " << fraction;
    }
  }
}

TEST(PcaStage, RejectsEvenWindows) {
  EXPECT_THROW(facet::testing::StageRunner<PcaStage>({{"window", std::int64_t{4}}}),
               facet::StageError);
}

}  // namespace
