// ChunkPlan and parallel_for: the ranges cover [0, count) exactly once whatever the runner, and
// without a runner the body runs inline over the whole range.
#include "facet/parallel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "facet/testing/reverse_runner.hpp"

namespace {

using facet::testing::ReverseRunner;

TEST(ChunkPlan, RangesCoverTheCountInOrderAndRespectTheMinimum) {
  for (const std::int64_t count : {1, 7, 31, 32, 100, 480}) {
    for (const std::int64_t min_chunk : {1, 8, 32}) {
      for (const int chunks : {1, 2, 8}) {
        const facet::ChunkPlan plan(count, min_chunk, chunks);
        ASSERT_GE(plan.size(), 1u);
        EXPECT_LE(plan.size(), static_cast<std::size_t>(chunks));
        EXPECT_EQ(plan.chunk_begin(0), 0);
        EXPECT_EQ(plan.chunk_begin(plan.size()), count);
        for (std::size_t i = 0; i < plan.size(); ++i) {
          const std::int64_t size = plan.chunk_begin(i + 1) - plan.chunk_begin(i);
          EXPECT_GT(size, 0);
          if (plan.size() > 1) {
            EXPECT_GE(size, min_chunk) << count << " " << min_chunk;
          }
        }
      }
    }
  }
}

TEST(ParallelFor, WithoutARunnerTheBodyRunsOnceOverEverything) {
  std::vector<std::pair<std::int64_t, std::int64_t>> calls;
  facet::parallel_for(nullptr, 100, 1,
                      [&](std::int64_t b, std::int64_t e) { calls.emplace_back(b, e); });
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0], std::make_pair(std::int64_t{0}, std::int64_t{100}));
  facet::parallel_for(nullptr, 0, 1, [&](std::int64_t, std::int64_t) { ADD_FAILURE(); });
}

TEST(ParallelFor, ARunnerGetsRangesThatCoverEveryItemOnce) {
  ReverseRunner runner(2);
  std::vector<int> runs(1000, 0);
  facet::parallel_for(&runner, 1000, 10, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t i = b; i < e; ++i)
      ++runs[static_cast<std::size_t>(i)];
  });
  EXPECT_EQ(runner.runs(), 1);
  EXPECT_TRUE(std::all_of(runs.begin(), runs.end(), [](int n) { return n == 1; }));
}

TEST(ParallelFor, TooLittleWorkForTwoRangesStaysInline) {
  ReverseRunner runner(4);
  int calls = 0;
  facet::parallel_for(&runner, 20, 32, [&](std::int64_t b, std::int64_t e) {
    ++calls;
    EXPECT_EQ(b, 0);
    EXPECT_EQ(e, 20);
  });
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(runner.runs(), 0);
}

TEST(WorkspacePool, ALeaseIsKeptForTheNextCaller) {
  facet::WorkspacePool<std::vector<int>> pool;
  std::vector<int>* first = nullptr;
  {
    auto lease = pool.lease();
    lease->resize(10);
    first = &*lease;
    auto second = pool.lease();
    EXPECT_NE(&*second, first) << "two holders share one workspace";
  }
  auto again = pool.lease();
  EXPECT_TRUE(&*again == first || again->empty());
}

}  // namespace
