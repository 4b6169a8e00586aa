#include "shape/superquadric_model.hpp"

#include <algorithm>
#include <cmath>

namespace facet::shape {
namespace {

double sigmoid(double x) {
  return 1.0 / (1.0 + std::exp(-x));
}

double logit_of_epsilon(double epsilon) {
  const double s =
      std::clamp((epsilon - kMinEpsilon) / (kMaxEpsilon - kMinEpsilon), 1e-3, 1 - 1e-3);
  return std::log(s / (1.0 - s));
}

// log(exp(a) + exp(b)) without overflow (F reaches 1e300 and beyond for far points at ε = 0.1),
// and the share exp(a) / (exp(a) + exp(b)) of its first term, from the same exponential.
struct LogSum {
  double log;
  double share_of_a;
};
LogSum log_add_exp(double a, double b) {
  const double high = std::max(a, b);
  const double ratio = std::exp(std::min(a, b) - high);  // the smaller term over the larger
  const double share_of_high = 1.0 / (1.0 + ratio);
  return {high + std::log1p(ratio), a >= b ? share_of_high : 1.0 - share_of_high};
}

Eigen::Matrix3d exp_so3(const Eigen::Vector3d& omega) {
  const double angle = omega.norm();
  if (angle < 1e-12) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

// Keeps |x| away from 0 so that log|x| and 1/x stay finite; the sign is kept.
double away_from_zero(double x) {
  constexpr double kTiny = 1e-12;
  return std::abs(x) < kTiny ? (x < 0.0 ? -kTiny : kTiny) : x;
}

}  // namespace

double SuperquadricState::epsilon1() const {
  return kMinEpsilon + (kMaxEpsilon - kMinEpsilon) * sigmoid(shape1_logit);
}
double SuperquadricState::epsilon2() const {
  return kMinEpsilon + (kMaxEpsilon - kMinEpsilon) * sigmoid(shape2_logit);
}

SuperquadricState SuperquadricState::moved(const ParamVector& step) const {
  SuperquadricState out = *this;
  out.log_size += step.segment<3>(0);
  out.shape1_logit += step(3);
  out.shape2_logit += step(4);
  out.translation_m += step.segment<3>(5);
  out.rotation = rotation * exp_so3(step.segment<3>(8));
  return out;
}

SuperquadricState SuperquadricState::from(const Eigen::Isometry3d& pose,
                                          const Eigen::Vector3d& size_m, double epsilon1,
                                          double epsilon2) {
  SuperquadricState state;
  state.rotation = pose.linear();
  state.translation_m = pose.translation();
  state.log_size = size_m.cwiseMax(1e-4).array().log();
  state.shape1_logit = logit_of_epsilon(epsilon1);
  state.shape2_logit = logit_of_epsilon(epsilon2);
  return state;
}

Superquadric SuperquadricState::to_superquadric() const {
  Superquadric sq;
  // Re-orthonormalise: many small rotation updates accumulate rounding.
  sq.pose.linear() = Eigen::Quaterniond(rotation).normalized().toRotationMatrix();
  sq.pose.translation() = translation_m;
  sq.size_m = size_m();
  sq.epsilon1 = epsilon1();
  sq.epsilon2 = epsilon2();
  return sq;
}

ResidualTerms::ResidualTerms(const SuperquadricState& of)
    : state(&of),
      to_local(of.rotation.transpose()),
      epsilon1(of.epsilon1()),
      epsilon2(of.epsilon2()) {
  const double s1 = sigmoid(of.shape1_logit);
  const double s2 = sigmoid(of.shape2_logit);
  d_epsilon1 = (kMaxEpsilon - kMinEpsilon) * s1 * (1.0 - s1);
  d_epsilon2 = (kMaxEpsilon - kMinEpsilon) * s2 * (1.0 - s2);
}

double radial_residual(const SuperquadricState& state, const Eigen::Vector3d& point_m,
                       ParamVector* gradient) {
  return radial_residual(ResidualTerms(state), point_m, gradient);
}

double radial_residual(const ResidualTerms& terms, const Eigen::Vector3d& point_m,
                       ParamVector* gradient) {
  const SuperquadricState& state = *terms.state;
  const double e1 = terms.epsilon1;
  const double e2 = terms.epsilon2;
  const Eigen::Vector3d p = terms.to_local * (point_m - state.translation_m);
  const double length = p.norm();
  const Eigen::Vector3d q(away_from_zero(p.x()), away_from_zero(p.y()), away_from_zero(p.z()));
  // All of F in logarithms: l_k = log|p_k / a_k|.
  const double l1 = std::log(std::abs(q.x())) - state.log_size.x();
  const double l2 = std::log(std::abs(q.y())) - state.log_size.y();
  const double l3 = std::log(std::abs(q.z())) - state.log_size.z();
  const double log_a = (2.0 / e2) * l1;
  const double log_b = (2.0 / e2) * l2;
  const LogSum s = log_add_exp(log_a, log_b);
  const double log_s = s.log;
  const double log_t = (e2 / e1) * log_s;
  const double log_c = (2.0 / e1) * l3;
  const LogSum f = log_add_exp(log_t, log_c);
  const double log_f = f.log;
  const double g = std::exp(-0.5 * e1 * log_f);  // F^(-ε1/2): 1 on the surface
  const double residual = length * (1.0 - g);
  if (gradient == nullptr) return residual;

  // Shares of the sums: w_a = A / (A + B), w_t = T / F.
  const double w_a = s.share_of_a;
  const double w_b = 1.0 - w_a;
  const double w_t = f.share_of_a;
  const double w_c = 1.0 - w_t;
  // d log F / d (p, s, ε).
  const double k = 2.0 / e1;
  const Eigen::Vector3d dlogf_dp(w_t * w_a * k / q.x(), w_t * w_b * k / q.y(), w_c * k / q.z());
  const Eigen::Vector3d dlogf_ds(-w_t * w_a * k, -w_t * w_b * k, -w_c * k);
  const double dlogf_de2 = w_t * (-(2.0 / (e1 * e2)) * (w_a * l1 + w_b * l2) + log_s / e1);
  const double dlogf_de1 = -w_t * log_s * e2 / (e1 * e1) - w_c * 2.0 * l3 / (e1 * e1);
  // r = |p| (1 − G), G = exp(−ε1/2 · log F).
  const double dr_dlogf = length * g * 0.5 * e1;
  Eigen::Vector3d dr_dp = dr_dlogf * dlogf_dp;
  if (length > 1e-12) dr_dp += (1.0 - g) * p / length;
  const double dr_de1 = dr_dlogf * dlogf_de1 + length * g * 0.5 * log_f;
  const double dr_de2 = dr_dlogf * dlogf_de2;
  // Chain through the parametrisation.
  ParamVector& out = *gradient;
  out.segment<3>(0) = dr_dlogf * dlogf_ds;
  out(3) = dr_de1 * terms.d_epsilon1;
  out(4) = dr_de2 * terms.d_epsilon2;
  // p = Rᵀ(x − t): dp/dt = −Rᵀ; with R·exp([ω]×), dp/dω = [p]×, so dr/dω = dr/dp × p.
  out.segment<3>(5) = -(state.rotation * dr_dp);
  out.segment<3>(8) = dr_dp.cross(p);
  return residual;
}

double support_extent_m(const SuperquadricState& state, const Eigen::Vector3d& direction) {
  // The superquadric is the unit ball of a nested norm ‖(‖(x/a1, y/a2)‖_p2, z/a3)‖_p1 with
  // p = 2/ε; its support function is the nested dual norm with q = p/(p − 1) = 2/(2 − ε).
  // ε is capped below 2 so that q stays finite.
  const Eigen::Vector3d m = state.rotation.transpose() * direction;
  const Eigen::Vector3d a = state.size_m();
  const double q1 = 2.0 / (2.0 - std::min(state.epsilon1(), 1.95));
  const double q2 = 2.0 / (2.0 - std::min(state.epsilon2(), 1.95));
  const double xy = std::pow(
      std::pow(std::abs(a.x() * m.x()), q2) + std::pow(std::abs(a.y() * m.y()), q2), 1.0 / q2);
  return std::pow(std::pow(xy, q1) + std::pow(std::abs(a.z() * m.z()), q1), 1.0 / q1);
}

}  // namespace facet::shape
