// planes.support's `up` parameter: "auto" or a vector "x,y,z" in the camera frame, parsed by
// its ParamTraits, so that `facet validate` refuses a bad value before the stage is built.
#include "planes/world_up.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "facet/param.hpp"
#include "planes/support_planes.hpp"

namespace {

using facet::planes::WorldUp;
using Traits = facet::ParamTraits<WorldUp>;

WorldUp parsed(const std::string& text) {
  auto result = Traits::parse(text);
  if (const auto* error = std::get_if<std::string>(&result)) {
    ADD_FAILURE() << "refused '" << text << "': " << *error;
    return {};
  }
  return std::get<WorldUp>(result);
}

std::string refusal(const std::string& text) {
  auto result = Traits::parse(text);
  if (const auto* error = std::get_if<std::string>(&result)) return *error;
  ADD_FAILURE() << "accepted '" << text << "'";
  return {};
}

TEST(WorldUp, AutoHasNoDirection) {
  EXPECT_FALSE(parsed("auto").direction.has_value());
  EXPECT_EQ(Traits::format(WorldUp{}), "auto");
}

TEST(WorldUp, AVectorIsNormalised) {
  const WorldUp level = parsed("0,-1,0");
  ASSERT_TRUE(level.direction.has_value());
  EXPECT_EQ(*level.direction, Eigen::Vector3f(0.0F, -1.0F, 0.0F));
  const WorldUp longer = parsed("0,-2.5,0");
  ASSERT_TRUE(longer.direction.has_value());
  EXPECT_EQ(*longer.direction, Eigen::Vector3f(0.0F, -1.0F, 0.0F));
  // Spaces around the numbers, exponents and signs are read as before.
  const WorldUp pitched = parsed(" 0 , -0.766 ,-6.43e-1 ");
  ASSERT_TRUE(pitched.direction.has_value());
  EXPECT_NEAR(pitched.direction->norm(), 1.0F, 1e-6F);
  EXPECT_TRUE(pitched.direction->isApprox(Eigen::Vector3f(0.0F, -0.766F, -0.643F).normalized()));
  EXPECT_EQ(*parsed("+1e-3,0,0").direction, Eigen::Vector3f(1.0F, 0.0F, 0.0F));
}

TEST(WorldUp, RefusesWhatIsNeitherAutoNorAVector) {
  const std::string kind = "up must be 'auto' or a non-zero vector 'x,y,z', not '";
  // Not auto (the word is exact), or the wrong number of fields.
  for (const std::string bad : {"", "up", "Auto", " auto", "0,-1", "0,-1,0,1", "0,-1,0,"}) {
    const std::string error = refusal(bad);
    EXPECT_EQ(error.rfind(kind + bad + "'", 0), 0u) << error;
    EXPECT_NE(error.find("3 comma-separated numbers are needed"), std::string::npos) << error;
  }
  // A field that is not a finite number.
  for (const std::string bad : {"a,b,c", "0,,1", "0,-1 0,0", "0,nan,1", "0,1e99,0", "0x1,0,0"}) {
    const std::string error = refusal(bad);
    EXPECT_EQ(error.rfind(kind + bad + "'", 0), 0u) << error;
    EXPECT_NE(error.find("is not a finite number"), std::string::npos) << error;
  }
  EXPECT_NE(refusal("a,b,c").find("'a' is not a finite number"), std::string::npos);
  // No direction.
  for (const std::string bad : {"0,0,0", "0,-0,0.0"}) {
    const std::string error = refusal(bad);
    EXPECT_EQ(error.rfind(kind + bad + "'", 0), 0u) << error;
    EXPECT_NE(error.find("a zero vector has no direction"), std::string::npos) << error;
  }
}

TEST(WorldUp, FormatReadsBack) {
  EXPECT_EQ(Traits::format(WorldUp{Eigen::Vector3f(0.0F, -1.0F, 0.0F)}), "0,-1,0");
  for (const std::string text : {"auto", "0,-1,0", "1,0,0", "0,-0.766,-0.643", "0.3,-2,5"}) {
    const WorldUp value = parsed(text);
    const WorldUp again = parsed(Traits::format(value));
    ASSERT_EQ(again.direction.has_value(), value.direction.has_value()) << text;
    if (value.direction) {
      EXPECT_TRUE(again.direction->isApprox(*value.direction, 1e-6F))
          << text << " -> " << Traits::format(value);
    }
  }
}

// The stage's spec carries the parser: its default is today's text, and a bad value fails the
// parameter check that graphs are validated with.
TEST(WorldUp, TheSpecChecksTheParameter) {
  const facet::StageSpec spec = facet::planes::SupportPlaneStage::spec();
  const facet::ParamSpec* up = spec.find_param("up");
  ASSERT_NE(up, nullptr);
  EXPECT_EQ(up->type, facet::ParamType::string);
  EXPECT_EQ(std::get<std::string>(up->default_value), "auto");
  EXPECT_FALSE(facet::check_param_value(*up, std::string("0,-0.766,-0.643")).has_value());
  const auto error = facet::check_param_value(*up, std::string("0,0,0"));
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("'0,0,0'"), std::string::npos) << *error;
}

}  // namespace
