// Runs of equal labels: every run found whole, in raster order, whatever its length against the
// 16-label blocks the search compares at once.
#include "facet/algo/label_runs.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <tuple>
#include <vector>

namespace facet::algo {
namespace {

using LabelRun = std::tuple<std::int32_t, std::size_t, std::size_t>;

std::vector<LabelRun> runs_by_definition(const std::vector<std::int32_t>& labels) {
  std::vector<LabelRun> runs;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (runs.empty() || std::get<0>(runs.back()) != labels[i]) {
      runs.emplace_back(labels[i], i, i + 1);
    } else {
      std::get<2>(runs.back()) = i + 1;
    }
  }
  return runs;
}

std::vector<LabelRun> runs_found(const std::vector<std::int32_t>& labels) {
  std::vector<LabelRun> runs;
  for_each_label_run(labels.data(), labels.size(),
                     [&](std::int32_t id, std::size_t begin, std::size_t end) {
                       runs.emplace_back(id, begin, end);
                     });
  return runs;
}

TEST(LabelRuns, RunsOfEveryLengthAreFoundWhole) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> length(1, 70);
  std::uniform_int_distribution<int> id(-2, 3);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::int32_t> labels;
    while (labels.size() < 1000)
      labels.insert(labels.end(), length(rng), id(rng));
    EXPECT_EQ(runs_found(labels), runs_by_definition(labels)) << "trial " << trial;
  }
}

TEST(LabelRuns, OneLabelEverywhereIsOneRun) {
  for (const std::size_t size : {1U, 15U, 16U, 17U, 33U, 640U}) {
    const std::vector<std::int32_t> labels(size, 5);
    EXPECT_EQ(runs_found(labels), (std::vector<LabelRun>{LabelRun{5, 0, size}})) << size;
    EXPECT_EQ(label_run_end(labels.data(), 0, labels.size()), size);
  }
}

TEST(LabelRuns, ADifferenceInTheLastPlaceOfABlockEndsTheRun) {
  std::vector<std::int32_t> labels(40, 1);
  labels[16] = 2;  // the last label of the first block compared after the run's start
  EXPECT_EQ(label_run_end(labels.data(), 0, labels.size()), 16U);
  EXPECT_EQ(label_run_end(labels.data(), 16, labels.size()), 17U);
  EXPECT_EQ(label_run_end(labels.data(), 17, labels.size()), 40U);
  // An empty image has no run.
  EXPECT_TRUE(runs_found({}).empty());
}

}  // namespace
}  // namespace facet::algo
