// facet::algo::RegionSizeRule: the smallest region kept, by the area it covers.
#include "facet/algo/region_size_rule.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace facet::algo {
namespace {

// The rule's boundary: min_px up to the reference depth, the same area beyond it, never fewer
// than far_min_px.
TEST(RegionSizeRule, FarRegionsNeedTheAreaTheMinimumCoversAtTheReferenceDepth) {
  const RegionSizeRule rule{100, 1.0, 50};
  EXPECT_TRUE(rule.keeps(100, 0.5));
  EXPECT_FALSE(rule.keeps(99, 0.5));
  EXPECT_FALSE(rule.keeps(99, 1.0));
  EXPECT_TRUE(rule.keeps(64, 1.25));  // 100 * (1 / 1.25)^2 = 64
  EXPECT_FALSE(rule.keeps(63, 1.25));
  EXPECT_TRUE(rule.keeps(50, 2.0));  // the area asks 25, the floor 50
  EXPECT_FALSE(rule.keeps(49, 2.0));
  EXPECT_FALSE(rule.keeps(99, std::numeric_limits<double>::quiet_NaN()));
  const RegionSizeRule fixed{100, 0.0, 50};
  EXPECT_FALSE(fixed.keeps(99, 3.0));
  EXPECT_TRUE(fixed.keeps(100, 3.0));
}

TEST(RegionSizeRule, TheSmallestRegionAnyDepthKeepsIsTheFloorOnlyWhenTheRuleIsOn) {
  EXPECT_EQ((RegionSizeRule{100, 1.0, 50}.smallest_px()), 50);
  EXPECT_EQ((RegionSizeRule{100, 0.0, 50}.smallest_px()), 100);
  EXPECT_EQ((RegionSizeRule{100, 1.0, 150}.smallest_px()), 100);  // a floor above min_px: off
}

}  // namespace
}  // namespace facet::algo
