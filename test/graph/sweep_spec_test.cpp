// --sweep node.param=start:stop:step: parsing, the values of an axis, grid expansion, and the
// checks against a graph's nodes and stages.
#include <gtest/gtest.h>

#include <facet/framework/registry.hpp>
#include <facet/framework/sweep_check.hpp>
#include <facet/framework/sweep_spec.hpp>
#include <map>

#include "graph_test_support.hpp"
#include "test_stages.hpp"

namespace facet {
namespace {

SweepAxis axis_of(const std::string& option) {
  auto parsed = parse_sweep_axis(option);
  if (const auto* error = std::get_if<std::string>(&parsed)) {
    ADD_FAILURE() << option << ": " << *error;
    return {};
  }
  return std::get<SweepAxis>(parsed);
}

std::string error_of(const std::string& option) {
  auto parsed = parse_sweep_axis(option);
  if (const auto* error = std::get_if<std::string>(&parsed)) return *error;
  ADD_FAILURE() << option << " was accepted";
  return {};
}

TEST(SweepSpec, ValuesAreStartPlusIStepWrittenWithTheBoundsPrecision) {
  const SweepAxis axis = axis_of("edges.threshold=0.80:0.90:0.01");
  EXPECT_EQ(axis.node, "edges");
  EXPECT_EQ(axis.param, "threshold");
  EXPECT_EQ(axis.key(), "edges.threshold");
  EXPECT_EQ(axis.decimals, 2);
  EXPECT_FALSE(axis.integral);
  // Eleven values although (0.90 - 0.80) / 0.01 is 9.999999999999998 in binary.
  ASSERT_EQ(axis.texts.size(), 11u);
  EXPECT_EQ(axis.texts.front(), "0.80");
  EXPECT_EQ(axis.texts[5], "0.85");
  EXPECT_EQ(axis.texts.back(), "0.90");
  // No accumulated error: the value is the double nearest to its text, not 0.8 + 0.01 + ...
  EXPECT_EQ(axis.values[7], 0.87);
  EXPECT_EQ(axis.values.back(), 0.9);
}

TEST(SweepSpec, ManySmallStepsDoNotDrift) {
  // A running sum of 0.005 is off by about 1e-15 after 200 additions; start + i * step, rounded
  // to the written precision, is the double nearest to each decimal value.
  const SweepAxis axis = axis_of("n.p=0:0.995:0.005");
  ASSERT_EQ(axis.values.size(), 200u);
  EXPECT_EQ(axis.values[100], 0.5);
  EXPECT_EQ(axis.values[199], 0.995);
  EXPECT_EQ(axis.texts[199], "0.995");
  EXPECT_EQ(axis.texts[7], "0.035");
}

TEST(SweepSpec, PrecisionFollowsTheMostPreciseBound) {
  const SweepAxis axis = axis_of("planes.distance_m=0.01:0.02:0.0025");
  EXPECT_EQ(axis.decimals, 4);
  EXPECT_EQ(axis.texts,
            (std::vector<std::string>{"0.0100", "0.0125", "0.0150", "0.0175", "0.0200"}));
  const SweepAxis exponent = axis_of("a.b=1e-3:3e-3:1e-3");
  EXPECT_EQ(exponent.texts, (std::vector<std::string>{"0.001", "0.002", "0.003"}));
}

TEST(SweepSpec, IntegerBoundsGiveIntegerTexts) {
  const SweepAxis axis = axis_of("normals.radius=1:7:2");
  EXPECT_TRUE(axis.integral);
  EXPECT_EQ(axis.texts, (std::vector<std::string>{"1", "3", "5", "7"}));
  EXPECT_FALSE(axis_of("normals.radius=1.0:7:2").integral);
}

TEST(SweepSpec, StopOffTheGridEndsAtTheLastValueBelowIt) {
  const SweepAxis axis = axis_of("a.b=0.8:0.9:0.03");
  EXPECT_EQ(axis.texts, (std::vector<std::string>{"0.80", "0.83", "0.86", "0.89"}));
}

TEST(SweepSpec, ZeroCrossingIsNotNegativeZero) {
  const SweepAxis axis = axis_of("a.b=-0.3:0.3:0.1");
  ASSERT_EQ(axis.texts.size(), 7u);
  EXPECT_EQ(axis.texts[3], "0.0");
  EXPECT_EQ(axis.texts[0], "-0.3");
}

TEST(SweepSpec, NameWithoutADotIsAGraphParameter) {
  const SweepAxis axis = axis_of("edge_threshold=0.80:0.90:0.05");
  EXPECT_TRUE(axis.is_graph_param());
  EXPECT_EQ(axis.node, "");
  EXPECT_EQ(axis.param, "edge_threshold");
  EXPECT_EQ(axis.key(), "edge_threshold");
  EXPECT_EQ(axis.texts, (std::vector<std::string>{"0.80", "0.85", "0.90"}));
  EXPECT_FALSE(axis_of("edges.threshold=0.8:0.9:0.1").is_graph_param());
}

TEST(SweepSpec, OnePointWhenStartIsStop) {
  EXPECT_EQ(axis_of("a.b=0.5:0.5:0.1").texts, (std::vector<std::string>{"0.5"}));
}

TEST(SweepSpec, BadSpecsSayWhatIsWrong) {
  EXPECT_EQ(error_of("edges.threshold=0.9:0.8:0.01"),
            "--sweep edges.threshold=0.9:0.8:0.01: start 0.9 is above stop 0.8; give start <= "
            "stop");
  EXPECT_NE(error_of("a.b=0:1:0").find("step must be positive, got 0"), std::string::npos);
  EXPECT_NE(error_of("a.b=0:1:-0.1").find("step must be positive, got -0.1"), std::string::npos);
  EXPECT_NE(error_of("a.b=0:1:0.001").find("1001 points; at most 200"), std::string::npos);
  EXPECT_NE(error_of("a.b=0:1").find("expected start:stop:step after the '='"), std::string::npos);
  EXPECT_NE(error_of("a.b").find("expected node.param=start:stop:step"), std::string::npos);
  EXPECT_NE(error_of("a.b.c=0:1:0.1").find("'a.b.c' is neither node.param nor a graph parameter"),
            std::string::npos);
  EXPECT_NE(error_of("1st=0:1:0.1").find("is neither node.param nor a graph parameter"),
            std::string::npos);
  EXPECT_NE(error_of("a.b=0:x:0.1").find("stop 'x' is not a number"), std::string::npos);
  EXPECT_NE(error_of("a.b=0:inf:0.1").find("stop 'inf' is not a number"), std::string::npos);
  EXPECT_NE(error_of("a.b=0:1:0.1abc").find("step '0.1abc' is not a number"), std::string::npos);
  // 200 points are allowed, 201 are not.
  EXPECT_EQ(axis_of("a.b=1:200:1").values.size(), 200u);
  EXPECT_NE(error_of("a.b=0:200:1").find("201 points; at most 200"), std::string::npos);
}

TEST(SweepGrid, FirstAxisVariesSlowest) {
  const std::vector<SweepAxis> axes = {axis_of("edges.threshold=0.8:0.9:0.1"),
                                       axis_of("planes.distance_m=0.010:0.012:0.001")};
  ASSERT_EQ(sweep_grid_size(axes), std::optional<std::size_t>(6));
  const auto points = expand_sweep_grid(axes);
  ASSERT_EQ(points.size(), 6u);
  EXPECT_EQ(points[0].name, "edges.threshold=0.8,planes.distance_m=0.010");
  EXPECT_EQ(points[1].name, "edges.threshold=0.8,planes.distance_m=0.011");
  EXPECT_EQ(points[3].name, "edges.threshold=0.9,planes.distance_m=0.010");
  EXPECT_EQ(points[5].index, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(points[4].sets, (std::vector<std::pair<std::string, std::string>>{
                                {"edges.threshold", "0.9"}, {"planes.distance_m", "0.011"}}));
}

TEST(SweepGrid, GraphParametersAreGivenAsParamsNotSets) {
  const auto points =
      expand_sweep_grid({axis_of("edge_threshold=0.8:0.9:0.1"), axis_of("median.size=3:5:2")});
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[1].name, "edge_threshold=0.8,median.size=5");
  using Assignments = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(points[1].params, (Assignments{{"edge_threshold", "0.8"}}));
  EXPECT_EQ(points[1].sets, (Assignments{{"median.size", "5"}}));
}

TEST(SweepGrid, OneAxisIsOnePointPerValue) {
  const auto points = expand_sweep_grid({axis_of("a.b=1:3:1")});
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[2].name, "a.b=3");
}

TEST(SweepGrid, GridsOver200PointsAreRefused) {
  const std::vector<SweepAxis> axes = {axis_of("a.b=1:20:1"), axis_of("c.d=1:11:1")};
  EXPECT_FALSE(sweep_grid_size(axes).has_value());
  EXPECT_TRUE(expand_sweep_grid(axes).empty());
  EXPECT_EQ(sweep_grid_size({axis_of("a.b=1:20:1"), axis_of("c.d=1:10:1")}),
            std::optional<std::size_t>(200));
}

// Checks against a graph: the in-process test stages of graph_test.
class SweepCheck : public ::testing::Test {
 protected:
  SweepCheck() {
    graph_test::add_test_stages(registry_);
    Diagnostics load;
    graph_ = graph_test::load(R"(facet: 1
nodes:
  source: {stage: io.frames, params: {path: /data}}
  median: {stage: filter.median, in: {depth: source.depth}}
  normals: {stage: normals.cross, in: {depth: median.depth}}
  edges: {stage: edges.angle, in: {normals: normals.normals}}
)",
                              load);
    EXPECT_FALSE(load.has_errors()) << load.str();
  }

  std::string check(const std::vector<std::string>& options,
                    const std::vector<std::pair<std::string, std::string>>& sets = {},
                    const std::map<std::string, std::string>& params = {}) {
    LoadOptions given;
    given.sets = sets;
    given.params = params;
    std::vector<SweepAxis> axes;
    for (const auto& option : options)
      axes.push_back(axis_of(option));
    Diagnostics diagnostics;
    check_sweep_axes(axes, graph_, registry_, given, diagnostics);
    return diagnostics.str();
  }

  Registry registry_;
  GraphSpec graph_;
};

TEST_F(SweepCheck, ValidAxesPass) {
  EXPECT_EQ(check({"edges.threshold=0.1:0.9:0.1", "normals.radius=1:10:1"}), "");
}

TEST_F(SweepCheck, UnknownNodeSuggestsTheClosest) {
  EXPECT_EQ(check({"egdes.threshold=0.1:0.9:0.1"}),
            "<command line>: error: --sweep egdes.threshold=0.1:0.9:0.1: unknown node 'egdes'; "
            "did you mean 'edges'?\n");
}

TEST_F(SweepCheck, UnknownParamSuggestsTheClosest) {
  EXPECT_EQ(check({"edges.treshold=0.1:0.9:0.1"}),
            "<command line>: error: --sweep edges.treshold=0.1:0.9:0.1: stage 'edges.angle' of "
            "node 'edges' has no parameter 'treshold'; did you mean 'threshold'?\n");
}

TEST_F(SweepCheck, OutOfRangeValuesAreRefused) {
  const std::string error = check({"edges.threshold=0.5:1.5:0.5"});
  EXPECT_NE(error.find("parameter 'threshold' of node 'edges' (real): value 1.5 is out of range"),
            std::string::npos)
      << error;
  const std::string radius = check({"normals.radius=0:4:2"});
  EXPECT_NE(radius.find("value 0 is out of range [1, 10]"), std::string::npos) << radius;
}

TEST_F(SweepCheck, ChoicesAreChecked) {
  // filter.median takes size 3 or 5 only: 4 is not one of them.
  const std::string error = check({"median.size=3:5:1"});
  EXPECT_NE(error.find("parameter 'size' of node 'median' (int)"), std::string::npos) << error;
  EXPECT_EQ(check({"median.size=3:5:2"}), "");
}

TEST_F(SweepCheck, IntegerParamsNeedIntegerSteps) {
  const std::string error = check({"normals.radius=1:5:0.5"});
  EXPECT_NE(error.find("parameter 'radius' of node 'normals' (int) takes whole numbers"),
            std::string::npos)
      << error;
}

TEST_F(SweepCheck, NonNumericParamsCannotBeSwept) {
  const std::string mode = check({"edges.mode=1:2:1"});
  EXPECT_NE(mode.find("parameter 'mode' of node 'edges' (string) is not numeric"),
            std::string::npos)
      << mode;
  const std::string loop = check({"source.loop=0:1:1"});
  EXPECT_NE(loop.find("(bool) is not numeric"), std::string::npos) << loop;
}

TEST_F(SweepCheck, TwiceOrAlsoSetIsRefused) {
  EXPECT_NE(check({"edges.threshold=0.1:0.2:0.1", "edges.threshold=0.3:0.4:0.1"})
                .find("'edges.threshold' is swept twice"),
            std::string::npos);
  EXPECT_NE(check({"edges.threshold=0.1:0.2:0.1"}, {{"edges.threshold", "0.5"}})
                .find("'edges.threshold' is also given by --set edges.threshold=0.5"),
            std::string::npos);
}

TEST_F(SweepCheck, GridOver200PointsNamesItsSize) {
  const std::string error = check({"edges.threshold=0.01:0.21:0.01", "normals.radius=1:10:1"});
  EXPECT_NE(error.find("the grid has 21 x 10 = 210 points; at most 200"), std::string::npos)
      << error;
}

TEST_F(SweepCheck, EveryBadAxisIsReported) {
  const std::string error = check({"egdes.threshold=0.1:0.2:0.1", "normals.radius=1:5:0.5"});
  EXPECT_NE(error.find("unknown node 'egdes'"), std::string::npos) << error;
  EXPECT_NE(error.find("takes whole numbers"), std::string::npos) << error;
}

// Graph parameters: checked through the node parameters written with their ${name}.
class SweepCheckGraphParam : public SweepCheck {
 protected:
  SweepCheckGraphParam() {
    Diagnostics load;
    graph_ = graph_test::load(R"(facet: 1
params: {theta: 0.85, radius: 2, folder: /data, unused: 1}
nodes:
  source: {stage: io.frames, params: {path: "${folder}"}}
  median: {stage: filter.median, in: {depth: source.depth}}
  normals: {stage: normals.cross, in: {depth: median.depth}, params: {radius: "${radius}"}}
  edges: {stage: edges.angle, in: {normals: normals.normals}, params: {threshold: "${theta}"}}
)",
                              load);
    EXPECT_FALSE(load.has_errors()) << load.str();
  }
};

TEST_F(SweepCheckGraphParam, ValuesAreCheckedAgainstTheNodeParametersItSets) {
  EXPECT_EQ(check({"theta=0.80:0.90:0.05", "radius=1:3:1"}), "");
  const std::string range = check({"theta=0.5:1.5:0.5"});
  EXPECT_NE(range.find("--sweep theta=0.5:1.5:0.5: graph parameter 'theta' sets parameter "
                       "'threshold' of node 'edges' (real): value 1.5 is out of range"),
            std::string::npos)
      << range;
  const std::string whole = check({"radius=1:5:0.5"});
  EXPECT_NE(whole.find("parameter 'radius' of node 'normals' (int) takes whole numbers"),
            std::string::npos)
      << whole;
  const std::string text = check({"folder=1:2:1"});
  EXPECT_NE(text.find("sets parameter 'path' of node 'source' (string) is not numeric"),
            std::string::npos)
      << text;
}

TEST_F(SweepCheckGraphParam, UnknownOrUnusedGraphParametersAreRefused) {
  EXPECT_EQ(check({"thta=0.8:0.9:0.1"}),
            "<command line>: error: --sweep thta=0.8:0.9:0.1: 'thta' is no node.param and no "
            "graph parameter; did you mean 'theta'?\n");
  EXPECT_NE(check({"unused=1:2:1"})
                .find("graph parameter 'unused' sets no node parameter (none is written with "
                      "${unused})"),
            std::string::npos);
}

TEST_F(SweepCheckGraphParam, ANodeParameterMovedTwiceOrAlsoGivenIsRefused) {
  const std::string both = check({"theta=0.8:0.9:0.1", "edges.threshold=0.8:0.9:0.1"});
  EXPECT_NE(both.find("--sweep theta=0.8:0.9:0.1: it sets edges.threshold, which --sweep "
                      "edges.threshold=0.8:0.9:0.1 sweeps too"),
            std::string::npos)
      << both;
  EXPECT_NE(check({"theta=0.8:0.9:0.1"}, {}, {{"theta", "0.7"}})
                .find("'theta' is also given by --param theta=0.7"),
            std::string::npos);
}

}  // namespace
}  // namespace facet
