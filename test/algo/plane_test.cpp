// algo::Plane and its fits: total least squares through points (PlaneMoments) and RANSAC with a
// least-squares refit, on exact and noisy planes, far from the camera, with outliers, and on
// degenerate point sets.
#include "facet/algo/plane.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

namespace facet::algo {
namespace {

// Points on the plane through `centre_m` with unit normal `normal`, on a grid of side `side_m`,
// displaced along the normal by Gaussian noise of `noise_m`.
std::vector<float> plane_points(const Eigen::Vector3f& normal, const Eigen::Vector3f& centre_m,
                                float side_m, int per_side, float noise_m, std::mt19937& rng) {
  const Eigen::Vector3f u = normal.unitOrthogonal();
  const Eigen::Vector3f v = normal.cross(u);
  std::normal_distribution<float> noise(0.0F, noise_m);
  std::vector<float> xyz;
  for (int i = 0; i < per_side; ++i) {
    for (int j = 0; j < per_side; ++j) {
      const float a = side_m * (static_cast<float>(i) / static_cast<float>(per_side - 1) - 0.5F);
      const float b = side_m * (static_cast<float>(j) / static_cast<float>(per_side - 1) - 0.5F);
      const Eigen::Vector3f p =
          centre_m + a * u + b * v + (noise_m > 0.0F ? noise(rng) : 0.0F) * normal;
      xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    }
  }
  return xyz;
}

TEST(Plane, ThroughAPointFacesTheCamera) {
  const Eigen::Vector3f point(0.1F, 0.2F, 1.5F);
  // Given a normal pointing away from the camera, the plane turns it round.
  const Plane plane = Plane::through(Eigen::Vector3f::UnitZ(), point);
  EXPECT_EQ(plane.normal, -Eigen::Vector3f::UnitZ());
  EXPECT_FLOAT_EQ(plane.offset_m, 1.5F);
  EXPECT_FLOAT_EQ(plane.signed_distance_m(point.data()), 0.0F);
  EXPECT_GT(plane.signed_distance_m(0.0F, 0.0F, 1.0F), 0.0F);  // the camera's side: in front
}

TEST(PlaneMoments, LeastSquaresFindsATiltedPlaneAndItsCentroid) {
  std::mt19937 rng(3);
  const Eigen::Vector3f normal = Eigen::Vector3f(0.2F, -0.9F, -0.4F).normalized();
  const Eigen::Vector3f centre(0.1F, 0.3F, 1.2F);
  const std::vector<float> xyz = plane_points(normal, centre, 0.4F, 40, 0.0F, rng);
  PlaneMoments moments;
  for (std::size_t i = 0; i < xyz.size(); i += 3)
    moments.add(xyz[i], xyz[i + 1], xyz[i + 2]);
  EXPECT_EQ(moments.count(), 1600);
  EXPECT_LT((moments.centroid_m().cast<float>() - centre).norm(), 1e-5F);
  const auto plane = moments.plane();
  ASSERT_TRUE(plane.has_value());
  EXPECT_GT(plane->normal.dot(normal), 1.0F - 1e-6F);
  EXPECT_NEAR(plane->offset_m, -normal.dot(centre), 1e-5F);
  EXPECT_GT(plane->offset_m, 0.0F);
}

TEST(PlaneMoments, AFarCentimetrePatchStillGivesItsPlane) {
  // A 1 cm square 4 m away, its points in float (0.5 µm steps there): the plane passes through
  // the patch within a micrometre, its normal within 0.06 degrees, so its distance from the
  // camera within 0.1 mm.
  std::mt19937 rng(5);
  const Eigen::Vector3f normal = Eigen::Vector3f(0.0F, -0.6F, -0.8F).normalized();
  const Eigen::Vector3f centre(0.5F, 0.8F, 4.0F);
  const auto plane = least_squares_plane(plane_points(normal, centre, 0.01F, 20, 0.0F, rng));
  ASSERT_TRUE(plane.has_value());
  EXPECT_LT(std::abs(plane->signed_distance_m(centre.data())), 1e-6F);
  EXPECT_GT(plane->normal.dot(normal), std::cos(1e-3F));
  EXPECT_NEAR(plane->offset_m, -normal.dot(centre), 1e-4F);
}

TEST(PlaneMoments, ItsFrameRunsAlongARectanglesSides) {
  // A 30 x 10 cm rectangle turned 30 degrees in a tilted plane: the frame's first axis runs along
  // its long side, the second along its short one, both in the plane and orthogonal.
  const Eigen::Vector3f normal = Eigen::Vector3f(0.1F, -0.7F, -0.7F).normalized();
  const Eigen::Vector3f side_a = normal.unitOrthogonal();
  const Eigen::Vector3f side_b = normal.cross(side_a);
  const float turn = std::acos(-1.0F) / 6.0F;
  const Eigen::Vector3f long_side = std::cos(turn) * side_a + std::sin(turn) * side_b;
  const Eigen::Vector3f short_side = normal.cross(long_side);
  PlaneMoments moments;
  for (int i = 0; i <= 60; ++i) {
    for (int j = 0; j <= 20; ++j) {
      const Eigen::Vector3f p = Eigen::Vector3f(0.2F, 0.1F, 1.3F) +
                                (0.005F * static_cast<float>(i) - 0.15F) * long_side +
                                (0.005F * static_cast<float>(j) - 0.05F) * short_side;
      moments.add(p.x(), p.y(), p.z());
    }
  }
  const auto frame = moments.frame();
  ASSERT_TRUE(frame.has_value());
  EXPECT_GT(std::abs(frame->axis_u.dot(long_side)), 1.0F - 1e-5F);
  EXPECT_GT(std::abs(frame->axis_v.dot(short_side)), 1.0F - 1e-5F);
  EXPECT_LT(std::abs(frame->axis_u.dot(frame->plane.normal)), 1e-5F);
  EXPECT_LT(std::abs(frame->axis_v.dot(frame->plane.normal)), 1e-5F);
  EXPECT_NEAR(frame->axis_u.norm(), 1.0F, 1e-6F);
  EXPECT_NEAR(frame->axis_v.norm(), 1.0F, 1e-6F);
  // The frame's plane is plane()'s.
  const auto plane = moments.plane();
  ASSERT_TRUE(plane.has_value());
  EXPECT_EQ(plane->normal, frame->plane.normal);
  EXPECT_EQ(plane->offset_m, frame->plane.offset_m);
}

TEST(PlaneMoments, NoPlaneThroughTooFewOrCollinearPoints) {
  EXPECT_FALSE(least_squares_plane(std::vector<float>{}).has_value());
  EXPECT_FALSE(least_squares_plane(std::vector<float>{0, 0, 1, 0.1F, 0, 1}).has_value());
  std::vector<float> line;
  for (int i = 0; i < 50; ++i)
    line.insert(line.end(), {0.01F * static_cast<float>(i), 0.2F, 1.0F});
  EXPECT_FALSE(least_squares_plane(line).has_value());
  const std::vector<float> one_point(30, 1.0F);
  EXPECT_FALSE(least_squares_plane(one_point).has_value());
}

// `count` points over the 80 cm square around `centre_m` on the plane with unit normal
// `normal`, each raised along it by a height drawn from [min_height_m, max_height_m): the objects
// on a table, as outliers. Appended to `xyz`.
void add_points_above(const Eigen::Vector3f& normal, const Eigen::Vector3f& centre_m, int count,
                      float min_height_m, float max_height_m, std::mt19937& rng,
                      std::vector<float>& xyz) {
  std::uniform_real_distribution<float> spread(-0.4F, 0.4F);
  std::uniform_real_distribution<float> height(min_height_m, max_height_m);
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3f p = centre_m + spread(rng) * normal.unitOrthogonal() +
                              spread(rng) * normal.cross(normal.unitOrthogonal()) +
                              height(rng) * normal;
    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  }
}

TEST(RansacPlane, FindsTheTableAmongOutliersAndRefitsItsNoise) {
  std::mt19937 scene(7);
  const Eigen::Vector3f normal = Eigen::Vector3f(0.0F, -0.85F, -0.53F).normalized();
  const Eigen::Vector3f centre(0.0F, 0.4F, 1.3F);
  std::vector<float> xyz = plane_points(normal, centre, 0.8F, 50, 0.001F, scene);
  // 30 % of the points scattered 5-30 cm in front of the table.
  add_points_above(normal, centre, 1070, 0.05F, 0.3F, scene, xyz);
  std::mt19937 rng(1);
  const auto plane = ransac_plane(xyz, RansacPlaneRule{}, rng);
  ASSERT_TRUE(plane.has_value());
  EXPECT_GT(plane->normal.dot(normal), std::cos(0.5F * 3.14159265F / 180.0F));
  EXPECT_NEAR(plane->offset_m, -normal.dot(centre), 0.001F);
  // The same seed, the same plane.
  std::mt19937 again(1);
  const auto repeated = ransac_plane(xyz, RansacPlaneRule{}, again);
  ASSERT_TRUE(repeated.has_value());
  EXPECT_EQ(repeated->normal, plane->normal);
  EXPECT_EQ(repeated->offset_m, plane->offset_m);
}

TEST(RansacPlane, HypothesesNeededFollowTheInlierShare) {
  // 1 - (1 - w³)^n ≥ 0.99: n = ceil(ln 0.01 / ln(1 - w³)).
  EXPECT_EQ(ransac_hypotheses_needed(0.3, 0.99), 169);
  EXPECT_EQ(ransac_hypotheses_needed(0.5, 0.99), 35);
  EXPECT_EQ(ransac_hypotheses_needed(0.9, 0.99), 4);
  EXPECT_EQ(ransac_hypotheses_needed(1.0, 0.99), 1);
  EXPECT_GT(ransac_hypotheses_needed(0.0, 0.99), 1000000);
  EXPECT_LT(ransac_hypotheses_needed(0.3, 0.9), ransac_hypotheses_needed(0.3, 0.99));
}

// A patch that spans a table, the floor below it and what stands on the table, where no normal
// edge closed between them: the table holds a third of the points, the floor 40 cm below as
// many, the rest is scattered above the table. 20 fixed hypotheses miss both planes in some
// draws; the adaptive rule draws until a triple of one plane's inliers is all but certain.
TEST(RansacPlane, AdaptiveHypothesesFindAPlaneThatHoldsAThirdOfThePoints) {
  std::mt19937 scene(3);
  const Eigen::Vector3f normal = Eigen::Vector3f(0.0F, -0.85F, -0.53F).normalized();
  const Eigen::Vector3f table_centre(0.0F, 0.3F, 1.2F);
  std::vector<float> xyz = plane_points(normal, table_centre, 0.8F, 30, 0.001F, scene);
  const std::vector<float> floor =
      plane_points(normal, table_centre - 0.4F * normal, 0.8F, 30, 0.001F, scene);
  xyz.insert(xyz.end(), floor.begin(), floor.end());
  add_points_above(normal, table_centre, 900, 0.02F, 0.3F, scene, xyz);
  const auto on_a_plane = [&](const std::optional<Plane>& plane) {
    if (!plane || plane->normal.dot(normal) < std::cos(2.0F * 3.14159265F / 180.0F)) return false;
    const float table_offset = -normal.dot(table_centre);
    return std::abs(plane->offset_m - table_offset) < 0.005F ||
           std::abs(plane->offset_m - (table_offset + 0.4F)) < 0.005F;
  };
  RansacPlaneRule fixed;
  fixed.inlier_distance_m = 0.005F;
  RansacPlaneRule adaptive = fixed;
  adaptive.confidence = 0.99;
  adaptive.max_iterations = 500;
  int fixed_found = 0;
  int adaptive_found = 0;
  constexpr int kDraws = 40;
  for (int seed = 1; seed <= kDraws; ++seed) {
    std::mt19937 rng(static_cast<std::uint32_t>(seed));
    fixed_found += on_a_plane(ransac_plane(xyz, fixed, rng)) ? 1 : 0;
    std::mt19937 again(static_cast<std::uint32_t>(seed));
    adaptive_found += on_a_plane(ransac_plane(xyz, adaptive, again)) ? 1 : 0;
  }
  EXPECT_EQ(adaptive_found, kDraws);
  EXPECT_LT(fixed_found, kDraws);
}

TEST(RansacPlane, NothingFromDegeneratePoints) {
  std::mt19937 rng(1);
  EXPECT_FALSE(ransac_plane(std::vector<float>{0, 0, 1, 1, 0, 1}, RansacPlaneRule{}, rng));
  // Every triple is one point: no hypothesis.
  const std::vector<float> one_point(300, 1.0F);
  EXPECT_FALSE(ransac_plane(one_point, RansacPlaneRule{}, rng).has_value());
}

}  // namespace
}  // namespace facet::algo
