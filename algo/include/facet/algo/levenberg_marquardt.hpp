#pragma once
// Levenberg–Marquardt for small dense least-squares problems (a handful of parameters, any
// number of residuals), the solver behind the superquadric fit and reusable for any model fit.
//
// The problem linearises itself: it hands back the normal equations of its residuals r(x) at a
// state, H = JᵀJ, g = Jᵀr and the cost ½ rᵀr, and moves a state by a step. The state need not be
// a vector (a pose with a rotation, sizes through their logarithm): only the step is. Each
// iteration solves (H + λ·diag(H) + ε·I) δ = −g, Marquardt's scaling, so parameters of different
// units (metres, radians, log sizes) need no common scale; ε keeps the system positive definite
// where a parameter has no curvature. A step that lowers the cost is taken and λ shrinks; one
// that does not is refused and λ grows.
//
// Usage:
//   struct MyProblem {
//     using State = ...;                                    // anything copyable
//     struct Linearisation { Eigen::Matrix<double, N, N> hessian;
//                            Eigen::Matrix<double, N, 1> gradient; double cost; ... };
//     Linearisation linearise(const State& state);
//     State moved(const State& state, const Eigen::Matrix<double, N, 1>& step) const;
//   };
//   LevenbergMarquardt<N> solver(options);
//   auto linearisation = problem.linearise(state);
//   const SolverSummary summary = solver.minimise(problem, state, linearisation);
// On return `state` is the best state found and `linearisation` its linearisation (whatever
// else the problem's Linearisation carries, a residual for reporting say, comes along).

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

namespace facet::algo {

// Why a minimisation ended.
enum class SolverStop {
  cost_converged,   // a taken step lowered the cost by less than relative_cost_tolerance
  step_converged,   // a taken step was shorter than step_tolerance
  max_iterations,   // max_iterations steps were tried
  damping_limit,    // λ grew beyond max_damping: no step lowers the cost any more
  non_finite_step,  // the system gave a step with NaN or infinity (a degenerate problem)
};

std::string_view to_string(SolverStop stop) noexcept;

struct SolverOptions {
  int max_iterations = 25;                // steps tried, taken or refused
  double initial_damping = 1e-3;          // λ at the start
  double damping_decrease = 3.0;          // λ /= this after a taken step ...
  double min_damping = 1e-9;              // ... down to this
  double damping_increase = 4.0;          // λ *= this after a refused step ...
  double max_damping = 1e8;               // ... and beyond this the solver gives up
  double relative_cost_tolerance = 1e-5;  // converged: (cost − new cost) / cost below this
  double step_tolerance = 1e-7;           // converged: |δ| below this (in the step's units)
  // ε = absolute_diagonal_floor + relative_diagonal_floor × max diag(H), added to every
  // diagonal entry of the damped system.
  double absolute_diagonal_floor = 1e-12;
  double relative_diagonal_floor = 1e-9;
};

struct SolverSummary {
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;   // steps tried
  int steps_taken = 0;  // of which lowered the cost
  SolverStop stop = SolverStop::max_iterations;

  bool converged() const {
    return stop == SolverStop::cost_converged || stop == SolverStop::step_converged;
  }
};

template <int kParams>
class LevenbergMarquardt {
 public:
  using Matrix = Eigen::Matrix<double, kParams, kParams>;
  using Vector = Eigen::Matrix<double, kParams, 1>;

  explicit LevenbergMarquardt(SolverOptions options = {}) : options_(options) {}

  template <typename Problem>
  SolverSummary minimise(Problem& problem, typename Problem::State& state,
                         typename Problem::Linearisation& current) const {
    SolverSummary summary;
    summary.initial_cost = current.cost;
    double damping = options_.initial_damping;
    for (int iteration = 0; iteration < options_.max_iterations; ++iteration) {
      summary.iterations = iteration + 1;
      Matrix system = current.hessian;
      system.diagonal() += damping * current.hessian.diagonal() +
                           Vector::Constant(options_.absolute_diagonal_floor +
                                            options_.relative_diagonal_floor *
                                                current.hessian.diagonal().maxCoeff());
      const Vector step = system.ldlt().solve(-current.gradient);
      if (!step.allFinite()) {
        summary.stop = SolverStop::non_finite_step;
        break;
      }
      auto candidate = problem.moved(state, step);
      auto next = problem.linearise(candidate);
      if (std::isfinite(next.cost) && next.cost < current.cost) {
        const double gain = (current.cost - next.cost) / std::max(current.cost, 1e-300);
        state = std::move(candidate);
        current = std::move(next);
        ++summary.steps_taken;
        damping = std::max(damping / options_.damping_decrease, options_.min_damping);
        if (gain < options_.relative_cost_tolerance) {
          summary.stop = SolverStop::cost_converged;
          break;
        }
        if (step.norm() < options_.step_tolerance) {
          summary.stop = SolverStop::step_converged;
          break;
        }
      } else {
        damping *= options_.damping_increase;
        if (damping > options_.max_damping) {
          summary.stop = SolverStop::damping_limit;
          break;
        }
      }
    }
    summary.final_cost = current.cost;
    return summary;
  }

 private:
  SolverOptions options_;
};

}  // namespace facet::algo
