#include "shape/superquadric_fit.hpp"

#include <cmath>
#include <random>

#include "shape/superquadric_model.hpp"

namespace facet::shape {
namespace {

using ParamMatrix = Eigen::Matrix<double, kSuperquadricParams, kSuperquadricParams>;

// Normal equations of one linearisation: H = JᵀJ, g = Jᵀr, cost = ½ rᵀr.
struct FitLinearisation {
  ParamMatrix hessian = ParamMatrix::Zero();
  ParamVector gradient = ParamVector::Zero();
  double cost = 0.0;
  double point_sum_sq_m2 = 0.0;  // Σ r² over the points only (the reported residual)
};

// The contact residual: signed height of the superquadric's lowest point above the plane.
double contact_residual_m(const SuperquadricState& state, const Plane& plane) {
  const Eigen::Vector3d up = plane.normal.normalized();
  return plane.signed_distance_m(state.translation_m) - support_extent_m(state, up);
}

// Terms besides the points: the support contact and the size prior.
struct Priors {
  const Plane* support = nullptr;
  double contact_weight = 0.0;
  Eigen::Vector3d initial_log_size = Eigen::Vector3d::Zero();
  double size_weight_m = 0.0;
};

// The points' residuals and Jacobian rows, kept between linearisations to spare allocations.
struct Workspace {
  Eigen::Matrix<double, Eigen::Dynamic, kSuperquadricParams> jacobian;
  Eigen::VectorXd residuals;
};

// The fit as a least-squares problem for algo::LevenbergMarquardt.
struct SuperquadricProblem {
  using State = SuperquadricState;
  using Linearisation = FitLinearisation;

  const std::vector<Eigen::Vector3d>& points;
  Priors priors;
  Workspace work;

  FitLinearisation linearise(const SuperquadricState& state);
  SuperquadricState moved(const SuperquadricState& state, const ParamVector& step) const {
    return state.moved(step);
  }
};

FitLinearisation SuperquadricProblem::linearise(const SuperquadricState& state) {
  FitLinearisation out;
  const auto count = static_cast<Eigen::Index>(points.size());
  work.jacobian.resize(count, kSuperquadricParams);
  work.residuals.resize(count);
  const ResidualTerms terms(state);
  ParamVector row;
  for (Eigen::Index i = 0; i < count; ++i) {
    work.residuals(i) = radial_residual(terms, points[static_cast<std::size_t>(i)], &row);
    work.jacobian.row(i) = row.transpose();
  }
  // One product over all rows instead of a rank-one update per point.
  out.hessian.noalias() = work.jacobian.transpose() * work.jacobian;
  out.gradient.noalias() = work.jacobian.transpose() * work.residuals;
  out.point_sum_sq_m2 = work.residuals.squaredNorm();
  double sum_sq = out.point_sum_sq_m2;
  if (priors.support != nullptr) {
    // One residual with eleven parameters: forward differences are cheap and simple here.
    const Plane& plane = *priors.support;
    const double r = priors.contact_weight * contact_residual_m(state, plane);
    constexpr double kStep = 1e-6;
    for (int k = 0; k < kSuperquadricParams; ++k) {
      ParamVector step = ParamVector::Zero();
      step(k) = kStep;
      row(k) = (priors.contact_weight * contact_residual_m(state.moved(step), plane) - r) / kStep;
    }
    out.hessian += row * row.transpose();
    out.gradient += r * row;
    sum_sq += r * r;
  }
  // The size prior: log sizes stay near the initial box unless the points say otherwise. Only
  // diagonal entries, so it is added directly.
  for (int k = 0; k < 3; ++k) {
    const double r = priors.size_weight_m * (state.log_size(k) - priors.initial_log_size(k));
    out.hessian(k, k) += priors.size_weight_m * priors.size_weight_m;
    out.gradient(k) += priors.size_weight_m * r;
    sum_sq += r * r;
  }
  out.cost = 0.5 * sum_sq;
  return out;
}

}  // namespace

std::vector<Eigen::Vector3d> subsample_points(const std::vector<Eigen::Vector3d>& points_m,
                                              int count, std::uint64_t seed) {
  if (count <= 0 || points_m.size() <= static_cast<std::size_t>(count)) return points_m;
  // Partial Fisher–Yates over indices. The raw mt19937_64 output is specified by the standard;
  // the std distributions are not, so the index is taken by modulo (its bias is negligible).
  std::vector<std::size_t> index(points_m.size());
  for (std::size_t i = 0; i < index.size(); ++i)
    index[i] = i;
  std::mt19937_64 random(seed);
  std::vector<Eigen::Vector3d> out;
  out.reserve(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    const std::size_t j = i + static_cast<std::size_t>(random() % (index.size() - i));
    std::swap(index[i], index[j]);
    out.push_back(points_m[index[i]]);
  }
  return out;
}

SuperquadricFit fit_superquadric(const std::vector<Eigen::Vector3d>& points_m,
                                 const OrientedBox& initial, const Plane* support,
                                 const SuperquadricFitOptions& options) {
  SuperquadricFit fit;
  const std::vector<Eigen::Vector3d> points =
      subsample_points(points_m, options.max_points, options.seed);
  fit.points_used = static_cast<int>(points.size());
  if (points.size() < 2 * static_cast<std::size_t>(kSuperquadricParams)) return fit;

  SuperquadricState state = SuperquadricState::from(
      initial.pose, initial.half_extents_m, options.initial_epsilon, options.initial_epsilon);
  // Both priors count like all points together: the contact residual as if every point had
  // that distance; the size prior as if every point were off by weight × mean size × Δlog size.
  const double all_points = std::sqrt(static_cast<double>(points.size()));
  Priors priors;
  priors.support = support;
  priors.contact_weight = options.support_weight * all_points;
  priors.initial_log_size = state.log_size;
  priors.size_weight_m = options.size_prior_weight * all_points * state.size_m().mean();
  SuperquadricProblem problem{points, priors, Workspace{}};
  FitLinearisation current = problem.linearise(state);
  fit.summary = algo::LevenbergMarquardt<kSuperquadricParams>(options.solver)
                    .minimise(problem, state, current);
  fit.superquadric = state.to_superquadric();
  fit.superquadric.residual =
      std::sqrt(current.point_sum_sq_m2 / static_cast<double>(points.size()));
  fit.superquadric.valid = fit.superquadric.size_m.allFinite() &&
                           fit.superquadric.pose.matrix().allFinite() &&
                           std::isfinite(fit.superquadric.residual);
  return fit;
}

}  // namespace facet::shape
