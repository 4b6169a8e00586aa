// facet::algo::LevenbergMarquardt: it reaches the minimum of classic least-squares problems, and
// its summary says why it stopped, with the costs and the number of steps, for each way out.
#include "facet/algo/levenberg_marquardt.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace facet::algo {
namespace {

using Vector2 = Eigen::Vector2d;
using Matrix2 = Eigen::Matrix2d;

struct Linearisation2 {
  Matrix2 hessian = Matrix2::Zero();
  Vector2 gradient = Vector2::Zero();
  double cost = 0.0;
  int evaluations = 0;  // something the solver carries along but does not read
};

// Rosenbrock's valley as residuals r1 = 10 (y − x²), r2 = 1 − x: a curved narrow valley with the
// minimum 0 at (1, 1), the textbook test of a damped Gauss–Newton method.
struct Rosenbrock {
  using State = Vector2;
  using Linearisation = Linearisation2;
  int evaluations = 0;

  Linearisation linearise(const State& s) {
    const Eigen::Vector2d r(10.0 * (s.y() - s.x() * s.x()), 1.0 - s.x());
    Eigen::Matrix2d jacobian;
    jacobian << -20.0 * s.x(), 10.0, -1.0, 0.0;
    Linearisation out;
    out.hessian = jacobian.transpose() * jacobian;
    out.gradient = jacobian.transpose() * r;
    out.cost = 0.5 * r.squaredNorm();
    out.evaluations = ++evaluations;
    return out;
  }
  State moved(const State& s, const Vector2& step) const { return s + step; }
};

// A circle through noise-free points, with a state that is not the step: the radius is kept as
// its logarithm, so the solver must go through moved() rather than add steps to a vector.
struct CircleState {
  Eigen::Vector2d centre;
  double log_radius = 0.0;
};

struct Linearisation3 {
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
  double cost = 0.0;
};

struct Circle {
  using State = CircleState;
  using Linearisation = Linearisation3;
  std::vector<Eigen::Vector2d> points;

  Linearisation linearise(const State& s) const {
    Linearisation out;
    const double radius = std::exp(s.log_radius);
    for (const Eigen::Vector2d& p : points) {
      const Eigen::Vector2d d = p - s.centre;
      const double distance = d.norm();
      const double r = distance - radius;
      const Eigen::Vector3d row(-d.x() / distance, -d.y() / distance, -radius);
      out.hessian += row * row.transpose();
      out.gradient += r * row;
      out.cost += 0.5 * r * r;
    }
    return out;
  }
  State moved(const State& s, const Eigen::Vector3d& step) const {
    return {s.centre + step.head<2>(), s.log_radius + step(2)};
  }
};

TEST(LevenbergMarquardt, ReachesTheMinimumOfRosenbrocksValleyAndSaysItConverged) {
  Rosenbrock problem;
  Vector2 state(-1.2, 1.0);
  Linearisation2 current = problem.linearise(state);
  SolverOptions options;
  options.max_iterations = 200;
  options.relative_cost_tolerance = 1e-12;
  const SolverSummary summary = LevenbergMarquardt<2>(options).minimise(problem, state, current);

  EXPECT_TRUE(summary.converged()) << to_string(summary.stop);
  EXPECT_NEAR(state.x(), 1.0, 1e-4);
  EXPECT_NEAR(state.y(), 1.0, 1e-4);
  EXPECT_DOUBLE_EQ(summary.initial_cost, 0.5 * (4.4 * 4.4 + 2.2 * 2.2));
  EXPECT_LT(summary.final_cost, 1e-8);
  EXPECT_EQ(summary.final_cost, current.cost);
  EXPECT_GT(summary.steps_taken, 0);
  EXPECT_LE(summary.steps_taken, summary.iterations);
  // The linearisation handed back is the one of the returned state, and it is the problem's
  // own, with what else it carries: the last taken step's evaluation, not the first.
  const Linearisation2 again = problem.linearise(state);
  EXPECT_EQ(current.cost, again.cost);
  EXPECT_EQ(current.gradient, again.gradient);
  EXPECT_GT(current.evaluations, 1);
}

TEST(LevenbergMarquardt, FitsACircleThroughAStateThatIsNotAVector) {
  Circle problem;
  const Eigen::Vector2d centre(0.3, -0.2);
  const double radius = 0.05;
  for (int i = 0; i < 12; ++i) {
    const double angle = 0.4 * i;  // an arc of 4.4 rad, not the whole circle
    problem.points.push_back(centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  CircleState state{{0.28, -0.17}, std::log(0.08)};
  Linearisation3 current = problem.linearise(state);
  const SolverSummary summary = LevenbergMarquardt<3>().minimise(problem, state, current);

  EXPECT_TRUE(summary.converged()) << to_string(summary.stop);
  EXPECT_NEAR(state.centre.x(), centre.x(), 1e-6);
  EXPECT_NEAR(state.centre.y(), centre.y(), 1e-6);
  EXPECT_NEAR(std::exp(state.log_radius), radius, 1e-6);
  EXPECT_LT(summary.final_cost, summary.initial_cost);
}

TEST(LevenbergMarquardt, StopsAtTheIterationLimitAndKeepsTheBestStateSoFar) {
  Rosenbrock problem;
  Vector2 state(-1.2, 1.0);
  Linearisation2 current = problem.linearise(state);
  SolverOptions options;
  options.max_iterations = 3;
  const SolverSummary summary = LevenbergMarquardt<2>(options).minimise(problem, state, current);

  EXPECT_EQ(summary.stop, SolverStop::max_iterations);
  EXPECT_EQ(summary.iterations, 3);
  EXPECT_FALSE(summary.converged());
  EXPECT_LT(summary.final_cost, summary.initial_cost);
  EXPECT_DOUBLE_EQ(current.cost, problem.linearise(state).cost);
}

// A problem whose gradient points uphill: no step lowers the cost, λ grows past its limit, and
// the state is left where it was.
struct Uphill {
  using State = Vector2;
  using Linearisation = Linearisation2;
  Linearisation linearise(const State& s) const {
    Linearisation out;
    out.hessian = Matrix2::Identity();
    out.gradient = -s;  // the true gradient of ½|s|² is +s
    out.cost = 0.5 * s.squaredNorm();
    return out;
  }
  State moved(const State& s, const Vector2& step) const { return s + step; }
};

TEST(LevenbergMarquardt, GivesUpWhenNoStepLowersTheCost) {
  Uphill problem;
  Vector2 state(1.0, 2.0);
  Linearisation2 current = problem.linearise(state);
  SolverOptions options;
  options.max_iterations = 1000;
  const SolverSummary summary = LevenbergMarquardt<2>(options).minimise(problem, state, current);

  EXPECT_EQ(summary.stop, SolverStop::damping_limit);
  EXPECT_EQ(summary.steps_taken, 0);
  EXPECT_EQ(state, Vector2(1.0, 2.0));
  EXPECT_EQ(summary.final_cost, summary.initial_cost);
  // λ = 1e-3 · 4^k passes 1e8 at k = 19.
  EXPECT_EQ(summary.iterations, 19);
}

struct NotANumber {
  using State = Vector2;
  using Linearisation = Linearisation2;
  Linearisation linearise(const State&) const {
    Linearisation out;
    out.hessian = Matrix2::Identity();
    out.gradient = Vector2(std::numeric_limits<double>::quiet_NaN(), 0.0);
    out.cost = 1.0;
    return out;
  }
  State moved(const State& s, const Vector2& step) const { return s + step; }
};

TEST(LevenbergMarquardt, StopsOnANonFiniteStepWithoutMovingTheState) {
  NotANumber problem;
  Vector2 state(0.5, 0.5);
  Linearisation2 current = problem.linearise(state);
  const SolverSummary summary = LevenbergMarquardt<2>().minimise(problem, state, current);

  EXPECT_EQ(summary.stop, SolverStop::non_finite_step);
  EXPECT_EQ(summary.iterations, 1);
  EXPECT_EQ(state, Vector2(0.5, 0.5));
}

TEST(LevenbergMarquardt, NamesEveryStopReason) {
  EXPECT_EQ(to_string(SolverStop::cost_converged), "cost_converged");
  EXPECT_EQ(to_string(SolverStop::step_converged), "step_converged");
  EXPECT_EQ(to_string(SolverStop::max_iterations), "max_iterations");
  EXPECT_EQ(to_string(SolverStop::damping_limit), "damping_limit");
  EXPECT_EQ(to_string(SolverStop::non_finite_step), "non_finite_step");
}

}  // namespace
}  // namespace facet::algo
