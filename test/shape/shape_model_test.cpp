// The pieces under the shape stages: the residual's analytic gradient, the support function, the
// PCA box and the grasp rule.
#include <gtest/gtest.h>

#include "shape/grasp_rule.hpp"
#include "shape/pca_box.hpp"
#include "shape/superquadric_model.hpp"

namespace facet::shape {
namespace {

SuperquadricState sample_state(double epsilon1, double epsilon2) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.05, -0.02, 0.9);
  return SuperquadricState::from(pose, {0.06, 0.035, 0.05}, epsilon1, epsilon2);
}

TEST(SuperquadricModel, AnalyticGradientMatchesCentralDifferences) {
  for (const double eps : {0.2, 0.8, 1.5}) {
    const SuperquadricState state = sample_state(eps, 1.1 * eps);
    for (const Eigen::Vector3d& point :
         {Eigen::Vector3d(0.08, -0.01, 0.93), Eigen::Vector3d(0.0, 0.03, 0.85),
          Eigen::Vector3d(0.06, 0.0, 0.9)}) {
      ParamVector analytic;
      radial_residual(state, point, &analytic);
      for (int k = 0; k < kSuperquadricParams; ++k) {
        ParamVector step = ParamVector::Zero();
        step(k) = 1e-6;
        const double numeric = (radial_residual(state.moved(step), point, nullptr) -
                                radial_residual(state.moved(-step), point, nullptr)) /
                               2e-6;
        EXPECT_NEAR(analytic(k), numeric, 1e-5 + 1e-4 * std::abs(numeric)) << "param " << k;
      }
    }
  }
}

TEST(SuperquadricModel, ResidualIsZeroOnTheSurfaceAndRadialOffIt) {
  const SuperquadricState state = sample_state(1.0, 1.0);  // an ellipsoid
  const Eigen::Isometry3d pose = state.to_superquadric().pose;
  const Eigen::Vector3d on_surface = pose * Eigen::Vector3d(0.06, 0.0, 0.0);
  EXPECT_NEAR(radial_residual(state, on_surface, nullptr), 0.0, 1e-12);
  EXPECT_NEAR(radial_residual(state, pose * Eigen::Vector3d(0.08, 0.0, 0.0), nullptr), 0.02, 1e-12);
}

TEST(SuperquadricModel, SupportExtentOfBoxAndEllipsoid) {
  SuperquadricState box =
      SuperquadricState::from(Eigen::Isometry3d::Identity(), {0.1, 0.2, 0.3}, 0.1, 0.1);
  EXPECT_NEAR(support_extent_m(box, Eigen::Vector3d::UnitZ()), 0.3, 1e-9);
  const Eigen::Vector3d diagonal = Eigen::Vector3d(1, 1, 0).normalized();
  // A near-box (ε = 0.1) reaches close to its corner: (0.1 + 0.2) / √2.
  EXPECT_NEAR(support_extent_m(box, diagonal), 0.3 / std::sqrt(2.0), 0.01);
  const SuperquadricState ellipsoid =
      SuperquadricState::from(Eigen::Isometry3d::Identity(), {0.1, 0.2, 0.3}, 1.0, 1.0);
  EXPECT_NEAR(support_extent_m(ellipsoid, diagonal), std::sqrt((0.01 + 0.04) / 2.0), 1e-9);
}

TEST(PcaBox, BoxOfBoxSurfacePointsHasZeroResidual) {
  std::vector<Eigen::Vector3d> points;
  for (int i = -10; i <= 10; ++i) {
    for (int j = -10; j <= 10; ++j) {
      points.emplace_back(0.05 * i / 10.0, 0.02 * j / 10.0, 0.01);
      points.emplace_back(0.05 * i / 10.0, 0.02 * j / 10.0, -0.01);
    }
  }
  const OrientedBox box = fit_pca_box(points);
  EXPECT_NEAR(box.half_extents_m.x(), 0.05, 1e-9);
  EXPECT_NEAR(box.half_extents_m.y(), 0.02, 1e-9);
  EXPECT_NEAR(box.half_extents_m.z(), 0.01, 1e-9);
  EXPECT_NEAR(box_surface_rms_m(box, points), 0.0, 1e-9);
  EXPECT_NEAR(distance_to_box_surface_m(box, {0.0, 0.0, 0.0}), 0.01, 1e-9);
  EXPECT_NEAR(distance_to_box_surface_m(box, {0.0, 0.0, 0.03}), 0.02, 1e-9);
  EXPECT_EQ(fit_pca_box({}).half_extents_m, Eigen::Vector3d::Zero());
}

TEST(GraspRule, SizeClasses) {
  const GraspRule rule;
  EXPECT_EQ(rule.classify({0.03, 0.02, 0.01}), GraspPrototype::pincer);
  EXPECT_EQ(rule.classify({0.12, 0.07, 0.05}), GraspPrototype::precision);
  EXPECT_EQ(rule.classify({0.12, 0.10, 0.09}), GraspPrototype::power);
  EXPECT_EQ(rule.classify({0.0, 0.0, 0.0}), GraspPrototype::none);
}

}  // namespace
}  // namespace facet::shape
