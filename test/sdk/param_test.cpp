#include "facet/param.hpp"

#include <gtest/gtest.h>

#include "facet/stage_spec.hpp"

namespace {

facet::ParamSpec spec_of(facet::ParamType type, facet::ParamValue value,
                         facet::ParamOptions options = {}) {
  return {"p", type, std::move(value), "doc", std::move(options)};
}

TEST(ParseParam, ParsesEachType) {
  using facet::ParamType;
  using facet::ParamValue;
  EXPECT_EQ(std::get<ParamValue>(
                facet::parse_param_value(spec_of(ParamType::integer, {std::int64_t{0}}), "42")),
            ParamValue(std::int64_t{42}));
  EXPECT_EQ(std::get<ParamValue>(facet::parse_param_value(spec_of(ParamType::real, 0.0), "0.85")),
            ParamValue(0.85));
  EXPECT_EQ(
      std::get<ParamValue>(facet::parse_param_value(spec_of(ParamType::boolean, false), "true")),
      ParamValue(true));
  EXPECT_EQ(std::get<ParamValue>(
                facet::parse_param_value(spec_of(ParamType::string, std::string()), "x y")),
            ParamValue(std::string("x y")));
}

TEST(ParseParam, RejectsMalformedText) {
  using facet::ParamType;
  EXPECT_EQ(facet::parse_param_value(spec_of(ParamType::integer, std::int64_t{0}), "4.5").index(),
            1u);
  EXPECT_EQ(facet::parse_param_value(spec_of(ParamType::integer, std::int64_t{0}), "").index(), 1u);
  EXPECT_EQ(facet::parse_param_value(spec_of(ParamType::real, 0.0), "abc").index(), 1u);
  EXPECT_EQ(facet::parse_param_value(spec_of(ParamType::real, 0.0), "nan").index(), 1u);
  EXPECT_EQ(facet::parse_param_value(spec_of(ParamType::boolean, false), "maybe").index(), 1u);
  const auto error = std::get<std::string>(
      facet::parse_param_value(spec_of(ParamType::integer, std::int64_t{0}), "4.5"));
  EXPECT_NE(error.find("integer"), std::string::npos) << error;
}

TEST(CheckParam, EnforcesRangeAndChoices) {
  const auto ranged = spec_of(facet::ParamType::real, 0.5, {.min = 0.0, .max = 1.0});
  EXPECT_FALSE(facet::check_param_value(ranged, 1.0).has_value());
  const auto out_of_range = facet::check_param_value(ranged, 1.5);
  ASSERT_TRUE(out_of_range.has_value());
  EXPECT_NE(out_of_range->find("out of range [0.0, 1.0]"), std::string::npos) << *out_of_range;

  const auto choice = spec_of(facet::ParamType::integer, std::int64_t{3}, {.choices = {3, 5}});
  EXPECT_FALSE(facet::check_param_value(choice, std::int64_t{5}).has_value());
  const auto not_a_choice = facet::check_param_value(choice, std::int64_t{4});
  ASSERT_TRUE(not_a_choice.has_value());
  EXPECT_NE(not_a_choice->find("3, 5"), std::string::npos) << *not_a_choice;
}

TEST(CheckParam, RejectsWrongType) {
  const auto integer = spec_of(facet::ParamType::integer, std::int64_t{1});
  EXPECT_TRUE(facet::check_param_value(integer, std::string("x")).has_value());
  EXPECT_TRUE(facet::check_param_value(integer, 1.5).has_value());
  // An integer is a fine value for a real parameter.
  const auto real = spec_of(facet::ParamType::real, 1.0);
  EXPECT_FALSE(facet::check_param_value(real, std::int64_t{2}).has_value());
}

TEST(Params, TypedAccessors) {
  facet::Params params;
  params.set("n", std::int64_t{3});
  params.set("x", 2.5);
  params.set("s", std::string("mm"));
  params.set("b", true);
  EXPECT_EQ(params.get_int("n"), 3);
  EXPECT_DOUBLE_EQ(params.get_double("x"), 2.5);
  EXPECT_DOUBLE_EQ(params.get_double("n"), 3.0);
  EXPECT_EQ(params.get_string("s"), "mm");
  EXPECT_TRUE(params.get_bool("b"));
  EXPECT_THROW(params.get_int("x"), std::out_of_range);
  EXPECT_THROW(params.get_int("missing"), std::out_of_range);
}

TEST(StageSpec, RejectsADefaultOutsideItsOwnRange) {
  facet::StageSpec spec("test.bad", "A stage with a broken declaration.");
  EXPECT_THROW(spec.param("threshold", 2.0, "doc", {.min = 0.0, .max = 1.0}), std::logic_error);
}

TEST(StageSpec, DefaultParamsHoldEveryDeclaredParameter) {
  facet::StageSpec spec("test.spec", "Summary line.\nMore detail.");
  spec.param("size", 3, "Window.", {.unit = "px", .choices = {3, 5}}).param("name", "x", "Name.");
  EXPECT_EQ(spec.summary(), "Summary line.");
  const auto params = spec.default_params();
  EXPECT_EQ(params.get_int("size"), 3);
  EXPECT_EQ(params.get_string("name"), "x");
  ASSERT_NE(spec.find_param("size"), nullptr);
  EXPECT_EQ(spec.find_param("size")->options.unit, "px");
  EXPECT_EQ(spec.find_param("nope"), nullptr);
}

}  // namespace
