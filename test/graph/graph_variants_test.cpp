#include "graph_test_support.hpp"

namespace facet {
namespace {

using graph_test::find_param;
using graph_test::load;
using graph_test::single_error;

constexpr const char* kVariantGraph = R"(facet: 1
nodes:
  source: {stage: io.frames}
  median: {stage: filter.median, in: {depth: source.depth}, params: {size: 3}}
  normals: {stage: normals.cross, in: {depth: median.depth}, params: {radius: 2}}
variants:
  big: {set: {median.size: 5}}
  pca: {replace: {normals: {stage: normals.pca, params: {window: 7}}}}
  raw: {replace: {normals: {in: {depth: source.depth}}}}
  bare: {replace: {normals: {stage: normals.pca}}}
  both: {extends: [big, pca], set: {median.size: 7, normals.window: 9}}
  bigger: {extends: big, set: {median.size: 9}}
)";

GraphSpec load_variant(const std::string& variant, Diagnostics& diagnostics,
                       LoadOptions options = {}) {
  options.variant = variant;
  return load(kVariantGraph, diagnostics, options);
}

TEST(GraphVariants, NoVariantLeavesTheGraphAsWritten) {
  Diagnostics diagnostics;
  const GraphSpec graph = load_variant("", diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  EXPECT_EQ(graph.variants,
            (std::vector<std::string>{"big", "pca", "raw", "bare", "both", "bigger"}));
  EXPECT_EQ(find_param(*graph.find_node("median"), "size")->text, "3");
  EXPECT_EQ(graph.find_node("normals")->stage, "normals.cross");
}

TEST(GraphVariants, SetOverridesAParamAndPointsAtTheVariant) {
  Diagnostics diagnostics;
  const GraphSpec graph = load_variant("big", diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  EXPECT_EQ(graph.variant, "big");
  const ParamSetting* size = find_param(*graph.find_node("median"), "size");
  EXPECT_EQ(size->text, "5");
  EXPECT_EQ(format_location(size->where), "g.yaml:7:28");
}

TEST(GraphVariants, ReplaceSwapsStageAndParamsButKeepsInputs) {
  Diagnostics diagnostics;
  const GraphSpec graph = load_variant("pca", diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  const NodeSpec& normals = *graph.find_node("normals");
  EXPECT_EQ(normals.stage, "normals.pca");
  EXPECT_EQ(normals.replaced_stage, "normals.cross");
  EXPECT_EQ(normals.replaced_by_variant, "pca");
  ASSERT_EQ(normals.params.size(), 1u);  // radius belonged to the replaced stage
  EXPECT_EQ(find_param(normals, "window")->text, "7");
  ASSERT_EQ(normals.inputs.size(), 1u);
  EXPECT_EQ(normals.inputs[0].from_node, "median");
}

TEST(GraphVariants, ReplacingTheStageWithoutParamsStartsFromItsDefaults) {
  Diagnostics diagnostics;
  const GraphSpec graph = load_variant("bare", diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  const NodeSpec& normals = *graph.find_node("normals");
  EXPECT_EQ(normals.stage, "normals.pca");
  EXPECT_TRUE(normals.params.empty());  // radius belonged to normals.cross
}

TEST(GraphVariants, ReplaceCanRewireInputsOnly) {
  Diagnostics diagnostics;
  const GraphSpec graph = load_variant("raw", diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  const NodeSpec& normals = *graph.find_node("normals");
  EXPECT_EQ(normals.stage, "normals.cross");
  EXPECT_TRUE(normals.replaced_by_variant.empty());
  EXPECT_EQ(normals.inputs[0].from_node, "source");
  EXPECT_EQ(find_param(normals, "radius")->text, "2");
}

TEST(GraphVariants, ExtendsAppliesBasesFirstInOrder) {
  Diagnostics diagnostics;
  const GraphSpec graph = load_variant("both", diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  EXPECT_EQ(find_param(*graph.find_node("median"), "size")->text, "7");
  const NodeSpec& normals = *graph.find_node("normals");
  EXPECT_EQ(normals.stage, "normals.pca");
  EXPECT_EQ(find_param(normals, "window")->text, "9");
}

TEST(GraphVariants, CommandLineSetWinsOverTheVariant) {
  LoadOptions options;
  options.sets = {{"median.size", "11"}};
  Diagnostics diagnostics;
  const GraphSpec graph = load_variant("bigger", diagnostics, options);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  EXPECT_EQ(find_param(*graph.find_node("median"), "size")->text, "11");
}

TEST(GraphVariants, UnknownVariantSuggestsAndListsTheVariants) {
  Diagnostics diagnostics;
  load_variant("bgi", diagnostics);
  EXPECT_EQ(diagnostics.str(),
            "<command line>: error: --variant bgi: unknown variant 'bgi'; did you mean 'big'?\n"
            "g.yaml: note: the graph defines: big, pca, raw, bare, both, bigger\n");
}

TEST(GraphVariants, UnknownVariantInAGraphWithoutVariants) {
  Diagnostics diagnostics;
  LoadOptions options;
  options.variant = "fast";
  load("facet: 1\nnodes: {a: {stage: x}}\n", diagnostics, options);
  EXPECT_EQ(diagnostics.str(),
            "<command line>: error: --variant fast: unknown variant 'fast'\n"
            "g.yaml: note: the graph defines no variants\n");
}

TEST(GraphVariants, EveryVariantIsCheckedEvenWhenNotSelected) {
  Diagnostics diagnostics;
  load(R"(facet: 1
nodes: {median: {stage: filter.median}}
variants:
  a: {set: {meddian.size: 5}}
  b: {replace: {normal: {stage: x}}, extends: c}
  c: {set: {nodot: 1}}
)",
       diagnostics);
  EXPECT_EQ(diagnostics.str(),
            "g.yaml:6:13: error: malformed key 'nodot' in 'set' of variant 'c': expected "
            "'node.param'\n"
            "g.yaml:4:13: error: unknown node 'meddian' in 'set' of variant 'a'; did you mean "
            "'median'?\n"
            "g.yaml:5:17: error: unknown node 'normal' in 'replace' of variant 'b'\n");
}

TEST(GraphVariants, UnknownBaseVariantIsReported) {
  Diagnostics diagnostics;
  load("facet: 1\nnodes: {a: {stage: x}}\nvariants:\n  big: {}\n  b: {extends: [bgi]}\n",
       diagnostics);
  EXPECT_EQ(single_error(diagnostics),
            "g.yaml:5:17: unknown variant 'bgi' in 'extends' of variant 'b'; did you mean 'big'?");
}

TEST(GraphVariants, ExtendsCycleIsReportedWithItsPath) {
  Diagnostics diagnostics;
  LoadOptions options;
  options.variant = "a";
  load(R"(facet: 1
nodes: {n: {stage: x}}
variants:
  a: {extends: b}
  b: {extends: [c]}
  c: {extends: a}
  d: {extends: d}
)",
       diagnostics, options);
  EXPECT_EQ(diagnostics.str(),
            "g.yaml:6:16: error: variant extends cycle: a -> b -> c -> a\n"
            "g.yaml:7:16: error: variant extends cycle: d -> d\n");
}

// A chain of 50 000 variants, each extending the next, overflowed the stack of the recursive
// walks (and 200 000 took quadratic time): the walks keep their own stack now.
TEST(GraphVariants, ALongExtendsChainIsWalkedWithoutRecursion) {
  constexpr int kChain = 50'000;
  std::string yaml = "facet: 1\nnodes: {n: {stage: x, params: {p: 0}}}\nvariants:\n";
  for (int i = 0; i < kChain; ++i) {
    yaml += "  v" + std::to_string(i) + ": {" +
            (i + 1 < kChain ? "extends: v" + std::to_string(i + 1) + ", " : std::string()) +
            "set: {n.p: " + std::to_string(i) + "}}\n";
  }
  LoadOptions options;
  options.variant = "v0";
  Diagnostics diagnostics;
  const GraphSpec graph = load(yaml, diagnostics, options);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str().substr(0, 500);
  // Bases first: the last in the chain sets p first, v0 itself last.
  EXPECT_EQ(find_param(*graph.find_node("n"), "p")->text, "0");

  // Closing the chain into a cycle is one error, its path shortened.
  yaml += "  w: {extends: v0}\n";
  yaml.replace(yaml.find("  v49999: {"), 11, "  v49999: {extends: v0, ");
  Diagnostics cycle;
  load(yaml, cycle, options);
  ASSERT_EQ(cycle.error_count(), 1) << cycle.str().substr(0, 500);
  EXPECT_NE(cycle.str().find(
                "v0 -> v1 -> v2 -> v3 -> ... (49993 more) -> v49997 -> v49998 -> v49999 -> v0"),
            std::string::npos)
      << cycle.str().substr(0, 500);
}

}  // namespace
}  // namespace facet
