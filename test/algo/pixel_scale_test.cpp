// facet::algo::PixelScale: pixel counts and lengths given for 640 x 480, scaled to a frame.
#include "facet/algo/pixel_scale.hpp"

#include <gtest/gtest.h>

#include "facet/algo/region_size_rule.hpp"

namespace facet::algo {
namespace {

// At the reference area nothing changes, not even by a rounding: 640 x 480 frames see the
// parameters exactly as given.
TEST(PixelScale, IsTheIdentityAtTheReferenceAreaAndWhenOff) {
  for (const PixelScale& scale :
       {PixelScale(kDefaultReferenceAreaPx, {640, 480}), PixelScale(0, {320, 240}),
        PixelScale(kDefaultReferenceAreaPx, {0, 0}), PixelScale()}) {
    EXPECT_EQ(scale.area_factor(), 1.0);
    EXPECT_EQ(scale.count(2500), 2500);
    EXPECT_EQ(scale.count(0, 0), 0);
    EXPECT_EQ(scale.length(8.0), 8.0);
  }
  // A 480 x 640 (portrait) frame has the reference's area.
  EXPECT_EQ(PixelScale(kDefaultReferenceAreaPx, {480, 640}).count(101), 101);
}

// Counts go with the area (rounded, never below the least), lengths with its square root.
TEST(PixelScale, CountsScaleWithTheAreaAndLengthsWithItsSquareRoot) {
  const PixelScale quarter(kDefaultReferenceAreaPx, {320, 240});
  EXPECT_DOUBLE_EQ(quarter.area_factor(), 0.25);
  EXPECT_EQ(quarter.count(100), 25);
  EXPECT_EQ(quarter.count(30), 8);  // 7.5 rounds up
  EXPECT_EQ(quarter.count(2), 1);   // 0.5 rounds to 1, and 1 is the least
  EXPECT_EQ(quarter.count(1), 1);
  EXPECT_EQ(quarter.count(10, 3), 3);
  EXPECT_EQ(quarter.count(0, 0), 0);  // an "off" value stays off
  EXPECT_DOUBLE_EQ(quarter.length(8.0), 4.0);

  const PixelScale four(kDefaultReferenceAreaPx, {1280, 960});
  EXPECT_EQ(four.count(2500), 10000);
  EXPECT_DOUBLE_EQ(four.length(12.0), 24.0);

  // Another reference: a graph tuned on 320 x 240 frames, run on 640 x 480 ones.
  EXPECT_EQ(PixelScale(320 * 240, {640, 480}).count(25), 100);
}

TEST(PixelScale, ScalesBothCountsOfARegionSizeRule) {
  const RegionSizeRule rule{100, 1.0, 50};
  const RegionSizeRule scaled = rule.scaled(PixelScale(kDefaultReferenceAreaPx, {320, 240}));
  EXPECT_EQ(scaled.min_px, 25);
  EXPECT_EQ(scaled.far_min_px, 13);  // 12.5 rounds up
  EXPECT_EQ(scaled.reference_depth_m, 1.0);
}

}  // namespace
}  // namespace facet::algo
