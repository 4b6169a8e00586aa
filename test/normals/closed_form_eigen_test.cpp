// The closed-form smallest eigenvector against Eigen's iterative solver on random covariances,
// including strongly anisotropic ones, and its refusal when the two smallest eigenvalues meet.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "normals/smallest_eigenvector_closed_form.hpp"

namespace {

using facet::normals::closed_form_smallest_eigenvector;
using facet::normals::Direction3;
using facet::normals::SymmetricMatrix3;

// Q diag(l0, l1, l2) Q^T for a random rotation Q.
Eigen::Matrix3d with_eigenvalues(std::mt19937& rng, double l0, double l1, double l2) {
  std::normal_distribution<double> normal;
  const Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  const Eigen::Matrix3d rotation = q.normalized().toRotationMatrix();
  return rotation * Eigen::Vector3d(l0, l1, l2).asDiagonal() * rotation.transpose();
}

SymmetricMatrix3 upper(const Eigen::Matrix3d& m) {
  return {m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)};
}

TEST(ClosedFormEigenvector, MatchesIterativeSolverWhenTrusted) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-4.0, 0.0);
  int trusted = 0;
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::pow(10.0, 6.0 * exponent(rng) / 4.0 + 1.0);  // any unit
    const double l2 = scale;
    const double l1 = scale * std::pow(10.0, exponent(rng));
    const double l0 = l1 * std::pow(10.0, exponent(rng) - 1.0);
    const Eigen::Matrix3d m = with_eigenvalues(rng, l0, l1, l2);
    Direction3 d{};
    if (!closed_form_smallest_eigenvector(upper(m), d)) continue;
    ++trusted;
    const Eigen::Vector3d v = Eigen::Vector3d(d.x, d.y, d.z).normalized();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
    worst = std::max(worst, 1.0 - std::abs(v.dot(solver.eigenvectors().col(0))));
  }
  EXPECT_GT(trusted, 19000);
  // 1 - |cos| < 1e-10: an angle below about 1.4e-5 rad.
  EXPECT_LT(worst, 1e-10);
}

TEST(ClosedFormEigenvector, RefusesCoincidingSmallestEigenvalues) {
  std::mt19937 rng(11);
  for (int i = 0; i < 100; ++i) {
    Direction3 d{};
    EXPECT_FALSE(closed_form_smallest_eigenvector(upper(with_eigenvalues(rng, 1.0, 1.0, 5.0)), d));
  }
  Direction3 d{};
  EXPECT_FALSE(closed_form_smallest_eigenvector(upper(Eigen::Matrix3d::Zero()), d));
  EXPECT_FALSE(closed_form_smallest_eigenvector(upper(Eigen::Matrix3d::Identity()), d));
}

}  // namespace
