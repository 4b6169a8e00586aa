#include "eval/assignment.hpp"

#include <limits>

namespace facet::eval {
namespace {

// Minimum-cost assignment of every row to a distinct column, rows <= cols, by shortest
// augmenting paths with potentials u (rows) and v (columns): each row is added in turn and the
// cheapest alternating path to a free column is found with Dijkstra on reduced costs, which the
// potentials keep non-negative. Index 0 is a virtual row/column, so arrays are 1-based.
std::vector<std::size_t> min_cost_rows_to_cols(const WeightMatrix& cost) {
  const std::size_t n = cost.rows;
  const std::size_t m = cost.cols;
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0);
  std::vector<double> v(m + 1, 0.0);
  std::vector<std::size_t> row_of_col(m + 1, 0);  // 0 = free
  std::vector<std::size_t> previous_col(m + 1, 0);
  for (std::size_t row = 1; row <= n; ++row) {
    row_of_col[0] = row;
    std::size_t col0 = 0;
    std::vector<double> min_reduced(m + 1, kInfinity);
    std::vector<bool> used(m + 1, false);
    do {
      used[col0] = true;
      const std::size_t row0 = row_of_col[col0];
      double delta = kInfinity;
      std::size_t next_col = 0;
      for (std::size_t col = 1; col <= m; ++col) {
        if (used[col]) continue;
        const double reduced = cost.at(row0 - 1, col - 1) - u[row0] - v[col];
        if (reduced < min_reduced[col]) {
          min_reduced[col] = reduced;
          previous_col[col] = col0;
        }
        if (min_reduced[col] < delta) {
          delta = min_reduced[col];
          next_col = col;
        }
      }
      for (std::size_t col = 0; col <= m; ++col) {
        if (used[col]) {
          u[row_of_col[col]] += delta;
          v[col] -= delta;
        } else {
          min_reduced[col] -= delta;
        }
      }
      col0 = next_col;
    } while (row_of_col[col0] != 0);
    // Flip the alternating path back to the virtual column.
    do {
      const std::size_t col1 = previous_col[col0];
      row_of_col[col0] = row_of_col[col1];
      col0 = col1;
    } while (col0 != 0);
  }
  std::vector<std::size_t> col_of_row(n, 0);
  for (std::size_t col = 1; col <= m; ++col) {
    if (row_of_col[col] != 0) col_of_row[row_of_col[col] - 1] = col - 1;
  }
  return col_of_row;
}

}  // namespace

std::vector<std::optional<std::size_t>> max_weight_assignment(const WeightMatrix& weights) {
  std::vector<std::optional<std::size_t>> assigned(weights.rows);
  if (weights.rows == 0 || weights.cols == 0) return assigned;
  // The method wants rows <= cols; the larger side is transposed away. Costs are negated
  // weights, so the minimum-cost assignment is the maximum-weight one.
  const bool transpose = weights.rows > weights.cols;
  WeightMatrix cost(transpose ? weights.cols : weights.rows,
                    transpose ? weights.rows : weights.cols);
  for (std::size_t r = 0; r < weights.rows; ++r) {
    for (std::size_t c = 0; c < weights.cols; ++c) {
      (transpose ? cost.at(c, r) : cost.at(r, c)) = -weights.at(r, c);
    }
  }
  const std::vector<std::size_t> matched = min_cost_rows_to_cols(cost);
  for (std::size_t i = 0; i < matched.size(); ++i) {
    if (transpose) {
      assigned[matched[i]] = i;
    } else {
      assigned[i] = matched[i];
    }
  }
  return assigned;
}

}  // namespace facet::eval
