#pragma once
// One-to-one assignment that maximises the total weight (the Hungarian method, O(n^3)).

#include <cstddef>
#include <optional>
#include <vector>

namespace facet::eval {

// A dense rows x cols matrix of weights, row-major.
struct WeightMatrix {
  std::size_t rows = 0;
  std::size_t cols = 0;
  std::vector<double> values;

  WeightMatrix(std::size_t row_count, std::size_t col_count)
      : rows(row_count), cols(col_count), values(row_count * col_count, 0.0) {}
  double& at(std::size_t row, std::size_t col) { return values[row * cols + col]; }
  double at(std::size_t row, std::size_t col) const { return values[row * cols + col]; }
};

// For every row, the column it is assigned to; min(rows, cols) rows get one, each column is used
// at most once, and the sum of the assigned weights is the largest possible. Rows left without a
// column (when rows > cols) are nullopt.
std::vector<std::optional<std::size_t>> max_weight_assignment(const WeightMatrix& weights);

}  // namespace facet::eval
