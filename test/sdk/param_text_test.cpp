// Comma-separated number lists, the text form of structured parameters (facet/param_text.hpp).
#include "facet/param_text.hpp"

#include <gtest/gtest.h>

#include <array>

namespace {

TEST(NumberList, ParsesExactlyTheCountAskedFor) {
  const auto parsed = facet::parse_number_list(" 0.5, -1 ,2e-3", 3);
  ASSERT_TRUE(std::holds_alternative<facet::NumberList>(parsed));
  const auto& list = std::get<facet::NumberList>(parsed);
  EXPECT_EQ(list.values, (std::vector<float>{0.5F, -1.0F, 2e-3F}));
  EXPECT_EQ(list.fields, (std::vector<std::string_view>{"0.5", "-1", "2e-3"}));
}

TEST(NumberList, SaysWhyTextIsRefused) {
  EXPECT_EQ(std::get<std::string>(facet::parse_number_list("1,2", 3)),
            "3 comma-separated numbers are needed, not 2");
  EXPECT_EQ(std::get<std::string>(facet::parse_number_list("1,,3", 3)),
            "'' is not a finite number");
  EXPECT_EQ(std::get<std::string>(facet::parse_number_list("1, x ,3", 3)),
            "'x' is not a finite number");
  EXPECT_EQ(std::get<std::string>(facet::parse_number_list("1,inf,3", 3)),
            "'inf' is not a finite number");
  EXPECT_EQ(std::get<std::string>(facet::parse_number_list("1,2 3,4", 3)),
            "'2 3' is not a finite number");
}

TEST(NumberList, FormatsEachFloatSoItReadsBackExactly) {
  const std::array<float, 4> values{0.1F, -1.0F, 1e-7F, 3.4028235e38F};
  const std::string text = facet::format_number_list(values);
  EXPECT_EQ(text.find(' '), std::string::npos) << text;
  const auto parsed = facet::parse_number_list(text, values.size());
  ASSERT_TRUE(std::holds_alternative<facet::NumberList>(parsed)) << text;
  EXPECT_EQ(std::get<facet::NumberList>(parsed).values,
            std::vector<float>(values.begin(), values.end()));
  EXPECT_EQ(facet::format_number_list(std::array<float, 3>{0.0F, -1.0F, 0.0F}), "0,-1,0");
}

}  // namespace
