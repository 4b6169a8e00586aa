// grow.blobs' `workspace` parameter: "" (no box) or "xmin,xmax,ymin,ymax,zmin,zmax" in metres,
// parsed by its ParamTraits, so that `facet validate` refuses a bad value before the stage is
// built.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "blobs/grow_blobs.hpp"
#include "blobs/workspace_box.hpp"
#include "facet/param.hpp"

namespace {

using facet::blobs::Workspace;
using Traits = facet::ParamTraits<Workspace>;

Workspace parsed(const std::string& text) {
  auto result = Traits::parse(text);
  if (const auto* error = std::get_if<std::string>(&result)) {
    ADD_FAILURE() << "refused '" << text << "': " << *error;
    return {};
  }
  return std::get<Workspace>(result);
}

std::string refusal(const std::string& text) {
  auto result = Traits::parse(text);
  if (const auto* error = std::get_if<std::string>(&result)) return *error;
  ADD_FAILURE() << "accepted '" << text << "'";
  return {};
}

TEST(Workspace, EmptyIsNoBox) {
  EXPECT_FALSE(parsed("").box.has_value());
  EXPECT_EQ(Traits::format(Workspace{}), "");
}

TEST(Workspace, ABoxIsMinAndMaxOfEachAxis) {
  const Workspace reach = parsed("-0.4,0.4,-0.5,0.3,0.5,1.2");
  ASSERT_TRUE(reach.box.has_value());
  EXPECT_EQ(reach.box->min(), Eigen::Vector3f(-0.4F, -0.5F, 0.5F));
  EXPECT_EQ(reach.box->max(), Eigen::Vector3f(0.4F, 0.3F, 1.2F));
  // Spaces around the numbers, exponents and signs are read as before.
  const Workspace spaced = parsed(" -5 , +5,-5e0, 5 ,0,1e1 ");
  ASSERT_TRUE(spaced.box.has_value());
  EXPECT_EQ(spaced.box->min(), Eigen::Vector3f(-5.0F, -5.0F, 0.0F));
  EXPECT_EQ(spaced.box->max(), Eigen::Vector3f(5.0F, 5.0F, 10.0F));
}

TEST(Workspace, RefusesWhatIsNotABox) {
  const std::string kind =
      "workspace must be empty or 'xmin,xmax,ymin,ymax,zmin,zmax' in metres with min < max, not '";
  // The wrong number of fields.
  for (const std::string bad : {" ", "1,2,3", "0,1,0,1,0,1,2", "0,1,0,1,0,1,"}) {
    const std::string error = refusal(bad);
    EXPECT_EQ(error.rfind(kind + bad + "'", 0), 0u) << error;
    EXPECT_NE(error.find("6 comma-separated numbers are needed"), std::string::npos) << error;
  }
  EXPECT_NE(refusal("1,2,3").find("needed, not 3"), std::string::npos);
  // A field that is not a finite number.
  for (const std::string bad : {"a,b,c,d,e,f", "0,1,,1,0,1", "0,1,0,1,0 1,2", "0,1,0,inf,0,1"}) {
    const std::string error = refusal(bad);
    EXPECT_EQ(error.rfind(kind + bad + "'", 0), 0u) << error;
    EXPECT_NE(error.find("is not a finite number"), std::string::npos) << error;
  }
  EXPECT_NE(refusal("a,b,c,d,e,f").find("'a' is not a finite number"), std::string::npos);
  // An empty or inverted axis.
  EXPECT_NE(refusal("1,0,0,1,0,1").find("xmin 1 is not below xmax 0"), std::string::npos);
  EXPECT_NE(refusal("0,1,0.5,0.5,0,1").find("ymin 0.5 is not below ymax 0.5"), std::string::npos);
  EXPECT_NE(refusal("0,1,0,1,2, 1 ").find("zmin 2 is not below zmax 1"), std::string::npos);
}

TEST(Workspace, FormatReadsBack) {
  EXPECT_EQ(Traits::format(parsed("-0.4,0.4,-0.5,0.3,0.5,1.2")), "-0.4,0.4,-0.5,0.3,0.5,1.2");
  for (const std::string text : {"", "-0.4,0.4,-0.5,0.3,0.5,1.2", "0.1,0.30000001,-3,7,1e-7,1e9"}) {
    const Workspace value = parsed(text);
    const Workspace again = parsed(Traits::format(value));
    ASSERT_EQ(again.box.has_value(), value.box.has_value()) << text;
    if (value.box) {
      EXPECT_EQ(again.box->min(), value.box->min()) << text;
      EXPECT_EQ(again.box->max(), value.box->max()) << text;
    }
  }
}

// The stage's spec carries the parser: its default is today's text, and a bad value fails the
// parameter check that graphs are validated with.
TEST(Workspace, TheSpecChecksTheParameter) {
  const facet::StageSpec spec = facet::blobs::GrowBlobs::spec();
  const facet::ParamSpec* workspace = spec.find_param("workspace");
  ASSERT_NE(workspace, nullptr);
  EXPECT_EQ(workspace->type, facet::ParamType::string);
  EXPECT_EQ(std::get<std::string>(workspace->default_value), "");
  EXPECT_FALSE(facet::check_param_value(*workspace, std::string("-1,1,-1,1,0.5,2")).has_value());
  const auto error = facet::check_param_value(*workspace, std::string("1,2,3"));
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("'1,2,3'"), std::string::npos) << *error;
}

}  // namespace
