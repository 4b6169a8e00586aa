#pragma once
// The superquadric's parameters as the fit sees them, and its residuals with their derivatives.
//
// Parametrisation (11 numbers, unconstrained, so LM never leaves the valid region):
//   sizes    a_k = exp(s_k)                        → a_k > 0
//   shapes   ε = 0.1 + 1.9 · sigmoid(e)            → ε in (0.1, 2)
//   position t (metres, camera frame)
//   rotation R · exp([ω]×), ω a local increment that is folded into R after every accepted step
// Order in the parameter vector: s1 s2 s3, e1 e2, t (3), ω (3).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "facet/types/geometry.hpp"

namespace facet::shape {

inline constexpr int kSuperquadricParams = 11;
inline constexpr double kMinEpsilon = 0.1;
inline constexpr double kMaxEpsilon = 2.0;

using ParamVector = Eigen::Matrix<double, kSuperquadricParams, 1>;

struct SuperquadricState {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // superquadric frame → camera frame
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d log_size = Eigen::Vector3d::Zero();
  double shape1_logit = 0.0;
  double shape2_logit = 0.0;

  double epsilon1() const;
  double epsilon2() const;
  Eigen::Vector3d size_m() const { return log_size.array().exp(); }

  // The state moved by `step` (ω applied on the right of the rotation).
  SuperquadricState moved(const ParamVector& step) const;

  static SuperquadricState from(const Eigen::Isometry3d& pose, const Eigen::Vector3d& size_m,
                                double epsilon1, double epsilon2);
  Superquadric to_superquadric() const;
};

// What the radial residual needs of a state that does not depend on the point, computed once
// per linearisation instead of once per point (the shapes alone cost six exponentials).
struct ResidualTerms {
  explicit ResidualTerms(const SuperquadricState& state);

  const SuperquadricState* state;
  Eigen::Matrix3d to_local;  // Rᵀ: camera frame → superquadric frame
  double epsilon1, epsilon2;
  double d_epsilon1, d_epsilon2;  // dε/d(logit)
};

// radial_residual() for a point, given its state's terms.
double radial_residual(const ResidualTerms& terms, const Eigen::Vector3d& point_m,
                       ParamVector* gradient);

// Radial distance of a camera-frame point to the surface: |p| · (1 − F(p)^(−ε1/2)), p the point
// in the superquadric's frame. F^(ε1/2) scales linearly along rays from the centre, so this is
// the distance along the ray through the centre (the usual "radial Euclidean" metric derived
// from F^ε1). When `gradient` is given it receives d residual / d parameters.
double radial_residual(const SuperquadricState& state, const Eigen::Vector3d& point_m,
                       ParamVector* gradient);

// Extent of the superquadric along the unit direction `direction` (camera frame), measured from
// its centre: the support function, exact for the nested-norm form of F.
double support_extent_m(const SuperquadricState& state, const Eigen::Vector3d& direction);

}  // namespace facet::shape
