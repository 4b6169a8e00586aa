// File-name ordering and glob matching used by io.frames.
#include "io/natural_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "io/frame_listing.hpp"

namespace {

using facet::io::natural_less;
using facet::io::wildcard_match;

TEST(NaturalOrder, NumbersCompareByValue) {
  std::vector<std::string> names = {"learn10.png",  "learn2.png",  "learn1.png",
                                    "learn100.png", "learn20.png", "test3.png"};
  std::sort(names.begin(), names.end(),
            [](const auto& a, const auto& b) { return natural_less(a, b); });
  EXPECT_EQ(names, (std::vector<std::string>{"learn1.png", "learn2.png", "learn10.png",
                                             "learn20.png", "learn100.png", "test3.png"}));
}

TEST(NaturalOrder, IsAStrictWeakOrder) {
  EXPECT_FALSE(natural_less("a1", "a1"));
  EXPECT_TRUE(natural_less("a1", "a01"));  // equal value: fewer leading zeros first
  EXPECT_FALSE(natural_less("a01", "a1"));
  EXPECT_TRUE(natural_less("000009", "000010"));
  EXPECT_TRUE(natural_less("a", "a1"));
  EXPECT_TRUE(natural_less("frame99999999999999999999", "frame100000000000000000000"));
}

TEST(Wildcard, MatchesStarsAndQuestionMarks) {
  EXPECT_TRUE(wildcard_match("*.png", "learn0.png"));
  EXPECT_TRUE(wildcard_match("learn2*.png", "learn20.png"));
  EXPECT_FALSE(wildcard_match("learn2*.png", "learn1.png"));
  EXPECT_TRUE(wildcard_match("f?.png", "f1.png"));
  EXPECT_FALSE(wildcard_match("f?.png", "f10.png"));
  EXPECT_TRUE(wildcard_match("*a*b*", "xxaybzz"));
  EXPECT_FALSE(wildcard_match("*.png", "depth.png.txt"));
}

}  // namespace
