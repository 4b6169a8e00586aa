#include "facet/algo/levenberg_marquardt.hpp"

namespace facet::algo {

std::string_view to_string(SolverStop stop) noexcept {
  switch (stop) {
    case SolverStop::cost_converged:
      return "cost_converged";
    case SolverStop::step_converged:
      return "step_converged";
    case SolverStop::max_iterations:
      return "max_iterations";
    case SolverStop::damping_limit:
      return "damping_limit";
    case SolverStop::non_finite_step:
      return "non_finite_step";
  }
  return "unknown";
}

}  // namespace facet::algo
