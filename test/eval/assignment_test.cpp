#include "eval/assignment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

namespace facet::eval {
namespace {

WeightMatrix matrix(std::size_t rows, std::size_t cols, std::initializer_list<double> values) {
  WeightMatrix weights(rows, cols);
  std::copy(values.begin(), values.end(), weights.values.begin());
  return weights;
}

double total(const WeightMatrix& weights, const std::vector<std::optional<std::size_t>>& rows) {
  double sum = 0.0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (rows[r]) sum += weights.at(r, *rows[r]);
  }
  return sum;
}

// The best total over every injective row -> column map, by enumeration (small sizes only).
double brute_force_best(const WeightMatrix& weights) {
  const bool transpose = weights.rows > weights.cols;
  const std::size_t small = std::min(weights.rows, weights.cols);
  const std::size_t large = std::max(weights.rows, weights.cols);
  std::vector<std::size_t> order(large);
  std::iota(order.begin(), order.end(), 0);
  double best = 0.0;
  do {
    double sum = 0.0;
    for (std::size_t i = 0; i < small; ++i) {
      sum += transpose ? weights.at(order[i], i) : weights.at(i, order[i]);
    }
    best = std::max(best, sum);
  } while (std::next_permutation(order.begin(), order.end()));
  return best;
}

TEST(MaxWeightAssignment, BeatsTheGreedyChoice) {
  // Greedy takes (0,0) = 0.9 and leaves row 1 nothing; the optimum gives up 0.1 for 0.8.
  const auto weights = matrix(3, 3, {0.9, 0.8, 0.0, 0.8, 0.0, 0.0, 0.0, 0.0, 0.5});
  const auto rows = max_weight_assignment(weights);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], 1u);
  EXPECT_EQ(rows[1], 0u);
  EXPECT_EQ(rows[2], 2u);
}

TEST(MaxWeightAssignment, MoreColumnsThanRows) {
  const auto weights = matrix(2, 3, {0.1, 0.2, 0.7, 0.6, 0.1, 0.65});
  const auto rows = max_weight_assignment(weights);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], 2u);
  EXPECT_EQ(rows[1], 0u);
}

TEST(MaxWeightAssignment, MoreRowsThanColumnsLeavesRowsUnassigned) {
  const auto weights = matrix(3, 1, {0.2, 0.9, 0.4});
  const auto rows = max_weight_assignment(weights);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_FALSE(rows[0].has_value());
  EXPECT_EQ(rows[1], 0u);
  EXPECT_FALSE(rows[2].has_value());
}

TEST(MaxWeightAssignment, EmptySides) {
  EXPECT_TRUE(max_weight_assignment(WeightMatrix(0, 4)).empty());
  const auto rows = max_weight_assignment(WeightMatrix(2, 0));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_FALSE(rows[0].has_value());
}

TEST(MaxWeightAssignment, MatchesEnumerationOnRandomMatrices) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> weight(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t rows = 1 + static_cast<std::size_t>(trial % 5);
    const std::size_t cols = 1 + static_cast<std::size_t>((trial / 5) % 6);
    WeightMatrix weights(rows, cols);
    for (double& value : weights.values)
      value = trial % 3 == 0 ? std::round(weight(random) * 3.0) / 3.0 : weight(random);
    const auto assigned = max_weight_assignment(weights);
    std::set<std::size_t> used;
    std::size_t count = 0;
    for (const auto& col : assigned) {
      if (!col) continue;
      ++count;
      EXPECT_TRUE(used.insert(*col).second) << "column used twice in trial " << trial;
    }
    EXPECT_EQ(count, std::min(rows, cols));
    EXPECT_NEAR(total(weights, assigned), brute_force_best(weights), 1e-9) << "trial " << trial;
  }
}

}  // namespace
}  // namespace facet::eval
