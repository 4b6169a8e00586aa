// normals.cross: which pixels get a normal (invalid depth, border), shift invariance in image
// space, and the smoothing options.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "normals/cross_stage.hpp"
#include "normals_test_support.hpp"

namespace {

using facet::normals::CrossStage;
using namespace facet::test;

constexpr int kRadius = 2;

// A tilted plane with a rectangular hole, two isolated invalid pixels and a row of holes.
RenderedScene plane_with_holes() {
  auto scene = SceneBuilder().plane({0.0, 0.0, 1.0}, tilted_normal(25.0, 70.0)).render();
  scene.depth_m(cv::Rect(200, 150, 30, 20)).setTo(0.0F);
  scene.depth_m.at<float>(300, 400) = 0.0F;
  scene.depth_m.at<float>(100, 100) = 0.0F;
  scene.depth_m(cv::Rect(350, 50, 200, 1)).setTo(0.0F);
  return scene;
}

// The pixels a triangle reads for pixel (u, v), the pixel itself included.
std::vector<cv::Point> used_pixels(const std::string& triangle, int u, int v, int r) {
  if (triangle == "paper") return {{u, v}, {u - r, v - r}, {u + r, v - r}, {u, v + r}};
  return {{u, v}, {u - r, v}, {u + r, v}, {u, v - r}, {u, v + r}};
}

// Elements that differ, where two NaNs count as equal.
int count_differences(const cv::Mat& a, const cv::Mat& b) {
  int different = 0;
  const cv::Mat fa = a.reshape(1);
  const cv::Mat fb = b.reshape(1);
  for (int v = 0; v < fa.rows; ++v) {
    for (int u = 0; u < fa.cols; ++u) {
      const float x = fa.at<float>(v, u);
      const float y = fb.at<float>(v, u);
      different += (std::isnan(x) && std::isnan(y)) || x == y ? 0 : 1;
    }
  }
  return different;
}

class CrossValidity : public ::testing::TestWithParam<std::tuple<const char*, const char*>> {};

// A pixel has a normal exactly when every pixel it reads is inside the image and valid: never a
// normal derived from an invalid depth, and no normal refused without reason.
TEST_P(CrossValidity, NormalExactlyWhereEveryUsedPixelIsValid) {
  const auto [space, triangle] = GetParam();
  const auto scene = plane_with_holes();
  const cv::Mat normals =
      run_normals<CrossStage>(scene.depth_mm_image(), {{"space", std::string(space)},
                                                       {"triangle", std::string(triangle)},
                                                       {"radius", std::int64_t{kRadius}}});
  const cv::Rect image(0, 0, normals.cols, normals.rows);
  int wrong = 0;
  int partly_nan = 0;
  for (int v = 0; v < normals.rows; ++v) {
    for (int u = 0; u < normals.cols; ++u) {
      bool all_valid = true;
      for (const auto& p : used_pixels(triangle, u, v, kRadius)) {
        all_valid = all_valid && image.contains(p) && scene.depth_m.at<float>(p) > 0.0F;
      }
      wrong += has_normal(normals, v, u) != all_valid ? 1 : 0;
      partly_nan += !has_normal(normals, v, u) && !is_all_nan(normals, v, u) ? 1 : 0;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(partly_nan, 0);
}

TEST_P(CrossValidity, BorderWithinRadiusHasNoNormal) {
  const auto [space, triangle] = GetParam();
  const auto scene = SceneBuilder().plane({0.0, 0.0, 1.0}, {0.0, 0.0, -1.0}).render();
  for (const std::int64_t r : {1, 2, 4}) {
    const cv::Mat normals = run_normals<CrossStage>(
        scene.depth_mm_image(),
        {{"space", std::string(space)}, {"triangle", std::string(triangle)}, {"radius", r}});
    for (int v = 0; v < normals.rows; ++v) {
      for (int u = 0; u < normals.cols; ++u) {
        const bool near_border = u < r || v < r || u >= normals.cols - r || v >= normals.rows - r;
        ASSERT_EQ(has_normal(normals, v, u), !near_border) << u << "," << v << " r=" << r;
      }
    }
  }
}

// The value stored in an invalid pixel (0, NaN, negative) never reaches any normal.
TEST_P(CrossValidity, InvalidValuesDoNotMatter) {
  const auto [space, triangle] = GetParam();
  const auto scene = plane_with_holes();
  const cv::Mat invalid = scene.depth_m == 0.0F;
  std::vector<cv::Mat> results;
  for (const float marker : {0.0F, std::numeric_limits<float>::quiet_NaN(), -3.0F}) {
    auto depth = scene.depth_m_image();
    depth.depth.setTo(marker, invalid);
    results.push_back(run_normals<CrossStage>(
        depth, {{"space", std::string(space)}, {"triangle", std::string(triangle)}}));
  }
  for (std::size_t i = 1; i < results.size(); ++i) {
    EXPECT_EQ(count_differences(results[0], results[i]), 0) << "marker " << i;
  }
}

// holes: one_sided. A pixel with depth whose triangle meets a hole takes the first one-sided
// tangent pair whose pixels all have depth; it stays without a normal only when none has. Every
// pixel the triangle served alone keeps exactly the normal it had.
TEST_P(CrossValidity, OneSidedNormalsBesideHolesExactlyWhereAPairIsValid) {
  const auto [space, triangle] = GetParam();
  const auto scene = plane_with_holes();
  const StageParams base{{"space", std::string(space)},
                         {"triangle", std::string(triangle)},
                         {"radius", std::int64_t{kRadius}}};
  StageParams one_sided = base;
  one_sided["holes"] = std::string("one_sided");
  const cv::Mat plain = run_normals<CrossStage>(scene.depth_mm_image(), base);
  const cv::Mat filled = run_normals<CrossStage>(scene.depth_mm_image(), one_sided);

  const cv::Rect image(0, 0, filled.cols, filled.rows);
  const auto valid = [&](cv::Point p) {
    return image.contains(p) && scene.depth_m.at<float>(p) > 0.0F;
  };
  int wrong = 0;
  int changed = 0;
  int gained = 0;
  for (int v = kRadius; v < filled.rows - kRadius; ++v) {
    for (int u = kRadius; u < filled.cols - kRadius; ++u) {
      if (has_normal(plain, v, u)) {
        changed += filled.at<cv::Vec3f>(v, u) != plain.at<cv::Vec3f>(v, u) ? 1 : 0;
        continue;
      }
      const bool horizontal = valid({u + kRadius, v}) || valid({u - kRadius, v});
      const bool vertical = valid({u, v + kRadius}) || valid({u, v - kRadius});
      const bool expected = valid({u, v}) && horizontal && vertical;
      wrong += has_normal(filled, v, u) != expected ? 1 : 0;
      gained += expected ? 1 : 0;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(changed, 0);
  EXPECT_GT(gained, 500);  // the ring around the rectangle, the single holes and the hole row
}

// On a plane, a one-sided normal is the plane's normal: in metric space every normal of the
// plane agrees, beside the holes as well as away from them.
TEST(CrossStage, OneSidedNormalsBesideHolesLieOnThePlane) {
  const auto scene = plane_with_holes();
  const StageParams params{{"space", std::string("metric")}, {"holes", std::string("one_sided")}};
  const cv::Mat normals = run_normals<CrossStage>(scene.depth_m_image(), params);
  const cv::Mat plain =
      run_normals<CrossStage>(scene.depth_m_image(), {{"space", std::string("metric")}});
  const Eigen::Vector3d reference = normal_at(plain, 400, 300);
  int beside_holes = 0;
  double worst_deg = 0.0;
  for (int v = 0; v < normals.rows; ++v) {
    for (int u = 0; u < normals.cols; ++u) {
      if (!has_normal(normals, v, u) || has_normal(plain, v, u)) continue;
      worst_deg = std::max(worst_deg, angle_deg(normal_at(normals, v, u), reference));
      ++beside_holes;
    }
  }
  EXPECT_GT(beside_holes, 500);
  EXPECT_LT(worst_deg, 0.5);
}

INSTANTIATE_TEST_SUITE_P(SpacesAndTriangles, CrossValidity,
                         ::testing::Combine(::testing::Values("image", "metric"),
                                            ::testing::Values("paper", "centred")));

// In image space only differences of pixel coordinates enter, so shifting the depth image
// shifts the normals exactly.
TEST(CrossStage, ShiftingTheImageShiftsTheNormals) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.05, 0.0, 0.9);
  pose.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 1.0, 0.0).normalized()).toRotationMatrix();
  const auto scene = SceneBuilder()
                         .plane({0.0, 0.0, 1.3}, tilted_normal(40.0, 90.0))
                         .box(pose, {0.1, 0.08, 0.06})
                         .render();
  const auto depth = scene.depth_mm_image();
  const int dx = 7;
  const int dy = 5;
  auto shifted = depth;
  // A new buffer: assigning Mat::zeros() would write into the one shared with `depth`.
  shifted.depth = cv::Mat(depth.depth.size(), depth.depth.type(), cv::Scalar(0));
  depth.depth(cv::Rect(0, 0, depth.depth.cols - dx, depth.depth.rows - dy))
      .copyTo(shifted.depth(cv::Rect(dx, dy, depth.depth.cols - dx, depth.depth.rows - dy)));

  for (const char* image_depth : {"disparity", "mm"}) {
    const StageParams params{{"space", std::string("image")},
                             {"image_depth", std::string(image_depth)},
                             {"smooth_radius", std::int64_t{1}}};
    const cv::Mat a = run_normals<CrossStage>(depth, params);
    const cv::Mat b = run_normals<CrossStage>(shifted, params);
    int compared = 0;
    int different = 0;
    // Away from the borders of both images (radius 2 plus smoothing 1).
    for (int v = 3; v < a.rows - dy - 3; ++v) {
      for (int u = 3; u < a.cols - dx - 3; ++u) {
        ASSERT_EQ(has_normal(a, v, u), has_normal(b, v + dy, u + dx)) << u << "," << v;
        if (!has_normal(a, v, u)) continue;
        different += a.at<cv::Vec3f>(v, u) != b.at<cv::Vec3f>(v + dy, u + dx) ? 1 : 0;
        ++compared;
      }
    }
    EXPECT_GT(compared, 200000);
    EXPECT_EQ(different, 0) << image_depth;
  }
}

// Smoothing over a plane changes nothing (all normals agree); at a crease, the mean of unit
// vectors is shorter than 1 unless renormalised.
TEST(CrossStage, SmoothingShortensNormalsOnlyWhereTheyDisagree) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 0.8);
  pose.linear() = Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const auto scene = SceneBuilder().box(pose, {0.12, 0.12, 0.12}).render();
  const auto depth = scene.depth_m_image();
  const StageParams base{{"space", std::string("metric")}};
  StageParams smooth = base;
  smooth["smooth_radius"] = std::int64_t{1};
  StageParams renormalized = smooth;
  renormalized["renormalize"] = true;
  const cv::Mat raw = run_normals<CrossStage>(depth, base);
  const cv::Mat averaged = run_normals<CrossStage>(depth, smooth);
  const cv::Mat unit = run_normals<CrossStage>(depth, renormalized);

  int interior = 0;
  int shortened = 0;
  for (int v = 3; v < raw.rows - 3; ++v) {
    for (int u = 3; u < raw.cols - 3; ++u) {
      // Smoothing never gives a normal to a pixel that had none, nor takes one away.
      ASSERT_EQ(has_normal(raw, v, u), has_normal(averaged, v, u));
      ASSERT_EQ(has_normal(raw, v, u), has_normal(unit, v, u));
      if (!has_normal(raw, v, u)) continue;
      EXPECT_NEAR(normal_at(unit, v, u).norm(), 1.0, 1e-5);
      bool one_face = true;
      for (int dv = -3; dv <= 3; ++dv) {
        for (int du = -3; du <= 3; ++du) {
          one_face = one_face && scene.face.at<int>(v + dv, u + du) == scene.face.at<int>(v, u);
        }
      }
      const double length = normal_at(averaged, v, u).norm();
      if (one_face) {
        EXPECT_NEAR(length, 1.0, 1e-4);
        EXPECT_LT(angle_deg(normal_at(averaged, v, u), normal_at(raw, v, u)), 0.05);
        ++interior;
      } else if (length < 0.99) {
        ++shortened;
      }
    }
  }
  EXPECT_GT(interior, 10000);
  EXPECT_GT(shortened, 100);  // along the box's vertical crease
}

TEST(CrossStage, RejectsMetricSpaceWithoutIntrinsics) {
  auto depth = SceneBuilder().plane({0.0, 0.0, 1.0}, {0.0, 0.0, -1.0}).render().depth_mm_image();
  depth.camera = {};
  EXPECT_THROW(run_normals<CrossStage>(depth, {{"space", std::string("metric")}}),
               facet::StageError);
  // Image space does not need them.
  EXPECT_NO_THROW(run_normals<CrossStage>(depth, {{"space", std::string("image")}}));
}

}  // namespace
