// facet::algo::DisjointSets: the smallest index is always the root, whatever the order of the
// unions, and one ascending flatten pass points every element at it.
#include "facet/algo/disjoint_sets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace facet::algo {
namespace {

TEST(DisjointSets, EveryElementStartsAsItsOwnSet) {
  DisjointSets sets;
  sets.reset(5);
  for (std::int32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(sets.find(i), i);
    EXPECT_TRUE(sets.is_root(i));
  }
}

TEST(DisjointSets, TheSmallestIndexIsTheRootWhateverTheOrderOfTheUnions) {
  DisjointSets sets;
  sets.reset(8);
  EXPECT_TRUE(sets.unite(6, 3));
  EXPECT_TRUE(sets.unite(7, 6));
  EXPECT_TRUE(sets.unite(5, 1));
  EXPECT_FALSE(sets.unite(3, 7));  // one set already
  EXPECT_TRUE(sets.unite(7, 5));
  for (const std::int32_t i : {1, 3, 5, 6, 7})
    EXPECT_EQ(sets.find(i), 1);
  for (const std::int32_t i : {0, 2, 4})
    EXPECT_EQ(sets.find(i), i);
}

// The same random unions in two orders give the same roots; flatten() in ascending order then
// leaves every element pointing at its root.
TEST(DisjointSets, FlattenInAscendingOrderPointsEveryElementAtItsRoot) {
  constexpr std::int32_t kCount = 2000;
  std::mt19937 random(11);
  std::uniform_int_distribution<std::int32_t> pick(0, kCount - 1);
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs(1500);
  for (auto& pair : pairs)
    pair = {pick(random), pick(random)};

  DisjointSets forward;
  forward.reset(kCount);
  for (const auto& [a, b] : pairs)
    forward.unite(a, b);
  DisjointSets backward;
  backward.reset(kCount);
  for (auto it = pairs.rbegin(); it != pairs.rend(); ++it)
    backward.unite(it->second, it->first);

  std::vector<std::int32_t> roots(kCount);
  for (std::int32_t i = 0; i < kCount; ++i) {
    roots[static_cast<std::size_t>(i)] = forward.find(i);
    EXPECT_EQ(backward.find(i), roots[static_cast<std::size_t>(i)]);
    EXPECT_LE(roots[static_cast<std::size_t>(i)], i);
  }
  for (std::int32_t i = 0; i < kCount; ++i)
    EXPECT_EQ(backward.flatten(i), roots[static_cast<std::size_t>(i)]);
  for (std::int32_t i = 0; i < kCount; ++i)
    EXPECT_EQ(backward.parent(i), roots[static_cast<std::size_t>(i)]);
}

// Only the elements made take part; reset keeps working after a smaller or larger size.
TEST(DisjointSets, ElementsMadeOneByOne) {
  DisjointSets sets;
  sets.reset_unmade(6);
  for (const std::int32_t i : {1, 2, 4})
    sets.make(i);
  sets.unite(4, 2);
  EXPECT_EQ(sets.find(4), 2);
  EXPECT_EQ(sets.find(1), 1);
  sets.reset(3);
  EXPECT_EQ(sets.size(), 3u);
  EXPECT_EQ(sets.find(2), 2);
}

}  // namespace
}  // namespace facet::algo
