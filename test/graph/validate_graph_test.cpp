#include <facet/framework/validated_graph.hpp>

#include "graph_test_support.hpp"
#include "test_stages.hpp"

namespace facet {
namespace {

using graph_test::single_error;

class ValidateGraph : public testing::Test {
 protected:
  ValidateGraph() { graph_test::add_test_stages(registry_); }

  // Loads and validates; loading must succeed so that each test is about validation.
  ValidatedGraph validate(const std::string& yaml, LoadOptions options = {}) {
    const GraphSpec graph = graph_test::load(yaml, diagnostics_, options);
    EXPECT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
    return validate_graph(graph, registry_, diagnostics_);
  }

  Registry registry_;
  Diagnostics diagnostics_;
};

constexpr const char* kPipeline = R"(facet: 1
nodes:
  write: {stage: io.depth, in: {depth: median.depth}, params: {dir: out}}
  edges: {stage: edges.angle, in: {normals: normals.normals}, params: {threshold: 1}}
  normals: {stage: normals.cross, in: {depth: median.depth}}
  median: {stage: filter.median, in: {depth: source.depth}, params: {size: 5}}
  source: {stage: io.frames, params: {path: rec, fps: 15, loop: yes}}
  other: {stage: io.frames, params: {path: rec2}}
)";

TEST_F(ValidateGraph, OrdersProducersFirstWithFileOrderTies) {
  const ValidatedGraph graph = validate(kPipeline);
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  std::vector<std::string> order;
  for (const auto& node : graph.nodes)
    order.push_back(node.id);
  EXPECT_EQ(order,
            (std::vector<std::string>{"source", "median", "write", "normals", "edges", "other"}));
}

TEST_F(ValidateGraph, ConnectionsIndexTheOrderedNodes) {
  const ValidatedGraph graph = validate(kPipeline);
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  const ValidatedNode* edges = graph.find("edges");
  ASSERT_NE(edges, nullptr);
  ASSERT_EQ(edges->inputs.size(), 2u);
  ASSERT_TRUE(edges->inputs[0].has_value());
  EXPECT_EQ(graph.nodes[edges->inputs[0]->from_node].id, "normals");
  EXPECT_EQ(edges->inputs[0]->from_port, 0u);
  EXPECT_FALSE(edges->inputs[1].has_value());  // optional depth left unconnected
  EXPECT_EQ(edges->stage->spec.name(), "edges.angle");
  EXPECT_EQ(graph.find("missing"), nullptr);
}

TEST_F(ValidateGraph, TypesParamsAndKeepsDefaults) {
  const ValidatedGraph graph = validate(kPipeline);
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  const Params& source = graph.find("source")->params;
  EXPECT_EQ(source.get_string("path"), "rec");
  EXPECT_TRUE(source.get_bool("loop"));
  // An integer written for a real parameter is stored as a real.
  EXPECT_TRUE(std::holds_alternative<double>(source.at("fps")));
  EXPECT_DOUBLE_EQ(source.get_double("fps"), 15.0);
  EXPECT_TRUE(std::holds_alternative<double>(graph.find("edges")->params.at("threshold")));
  EXPECT_EQ(graph.find("median")->params.get_int("size"), 5);
  EXPECT_EQ(graph.find("normals")->params.get_int("radius"), 2);  // default
  EXPECT_EQ(graph.find("edges")->params.get_string("mode"), "angle");
}

// Both sinks name their files after the frame: in one folder they overwrite each other.
TEST_F(ValidateGraph, TwoSinksWritingOneFolderAreAnError) {
  validate(R"(facet: 1
nodes:
  source: {stage: io.frames, params: {path: rec}}
  a: {stage: io.depth, in: {depth: source.depth}, params: {dir: out/depth}}
  b: {stage: io.depth, in: {depth: source.depth}, params: {dir: out/./depth/}}
  c: {stage: io.depth, in: {depth: source.depth}, params: {dir: out/other}}
)");
  EXPECT_EQ(single_error(diagnostics_),
            "g.yaml:5:3: node 'b' writes to folder 'out/./depth/', as node 'a' does: their "
            "files would overwrite each other; give each sink its own dir");
}

TEST_F(ValidateGraph, ANodeWhoseOutputsNothingReadsIsAWarning) {
  const ValidatedGraph graph = validate(R"(facet: 1
nodes:
  source: {stage: io.frames, params: {path: rec}}
  median: {stage: filter.median, in: {depth: source.depth}}
  write: {stage: io.depth, in: {depth: source.depth}, params: {dir: out}}
)");
  EXPECT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  EXPECT_EQ(graph.nodes.size(), 3U);
  EXPECT_NE(diagnostics_.str().find("g.yaml:4:3: warning: node 'median' (filter.median): nothing "
                                    "reads its outputs"),
            std::string::npos)
      << diagnostics_.str();
  // The source is read (by the sink), the sink has no outputs: no other warning.
  EXPECT_EQ(diagnostics_.str().find("'source'"), std::string::npos) << diagnostics_.str();
  EXPECT_EQ(diagnostics_.str().find("'write'"), std::string::npos) << diagnostics_.str();
}

TEST_F(ValidateGraph, UnknownStageSuggestsAName) {
  validate("facet: 1\nnodes:\n  m: {stage: filter.medain}\n");
  EXPECT_EQ(single_error(diagnostics_),
            "g.yaml:3:14: unknown stage 'filter.medain' for node 'm'; did you mean "
            "'filter.median'?");
}

TEST_F(ValidateGraph, UnknownStageListsPluginLoadFailures) {
  registry_.add_failure({"plugins/libfacet_planes.so", "undefined symbol: foo"});
  validate("facet: 1\nnodes:\n  p: {stage: planes.ransac}\n");
  EXPECT_EQ(diagnostics_.str(),
            "g.yaml:3:14: error: unknown stage 'planes.ransac' for node 'p'\n"
            "note: it may be provided by a plugin that failed to load: "
            "plugins/libfacet_planes.so: undefined symbol: foo\n");
}

TEST_F(ValidateGraph, UnknownParamSuggestsOrListsTheParams) {
  validate(R"(facet: 1
nodes:
  s: {stage: io.frames, params: {path: x, fsp: 3}}
  m: {stage: filter.median, in: {depth: s.depth}, params: {colour: red}}
)");
  EXPECT_EQ(diagnostics_.str(),
            "g.yaml:3:48: error: stage 'io.frames' has no parameter 'fsp'; did you mean 'fps'?\n"
            "g.yaml:4:68: error: stage 'filter.median' has no parameter 'colour'; its parameters "
            "are: size\n");
}

TEST_F(ValidateGraph, WrongTypeOutOfRangeAndChoices) {
  validate(R"(facet: 1
nodes:
  s: {stage: io.frames, params: {path: x, fps: fast, loop: maybe}}
  m: {stage: filter.median, in: {depth: s.depth}, params: {size: 4}}
  n: {stage: normals.cross, in: {depth: m.depth}, params: {radius: 11, max_jump: -0.5}}
  e: {stage: edges.angle, in: {normals: n.normals}, params: {mode: cosine, threshold: 0.25}}
)");
  EXPECT_EQ(diagnostics_.str(),
            "g.yaml:3:48: error: parameter 'fps' of node 's' (real): expected a number, got "
            "'fast'\n"
            "g.yaml:3:60: error: parameter 'loop' of node 's' (bool): expected a boolean (true or "
            "false), got 'maybe'\n"
            "g.yaml:4:66: error: parameter 'size' of node 'm' (int): value '4' is not one of 3, 5\n"
            "g.yaml:5:68: error: parameter 'radius' of node 'n' (int): value 11 is out of range "
            "[1, 10]\n"
            "g.yaml:5:82: error: parameter 'max_jump' of node 'n' (real): value -0.5 is out of "
            "range [0.0, inf]\n"
            "g.yaml:6:68: error: parameter 'mode' of node 'e' (string): value 'cosine' is not one "
            "of angle, dot\n");
}

// A structured parameter (facet::Param<T> with ParamTraits<T>) is parsed by validation, so a bad
// value is reported at its place in the file before any stage is built.
TEST_F(ValidateGraph, AStructuredValueIsParsedWithItsPlace) {
  const ValidatedGraph graph = validate(R"(facet: 1
nodes:
  s: {stage: io.frames, params: {path: x}}
  c: {stage: filter.crop, in: {depth: s.depth}, params: {extent: 300x}}
)");
  EXPECT_EQ(single_error(diagnostics_),
            "g.yaml:4:66: parameter 'extent' of node 'c' (string): expected 'WxH' in whole "
            "millimetres, e.g. '300x200', got '300x'");
}

TEST_F(ValidateGraph, AStructuredValueThatParsesIsKept) {
  const ValidatedGraph graph = validate(R"(facet: 1
nodes:
  s: {stage: io.frames, params: {path: x}}
  c: {stage: filter.crop, in: {depth: s.depth}, params: {extent: 300x200}}
)");
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  const graph_test::Extent extent = graph_test::kCropExtent(graph.find("c")->params);
  EXPECT_EQ(extent.width_mm, 300);
  EXPECT_EQ(extent.height_mm, 200);
}

TEST_F(ValidateGraph, RequiredParamMustBeSet) {
  validate("facet: 1\nnodes:\n  s: {stage: io.frames}\n");
  EXPECT_EQ(single_error(diagnostics_),
            "g.yaml:3:3: node 's': required parameter 'path' (string) of stage 'io.frames' is not "
            "set");
}

TEST_F(ValidateGraph, CommandLineSetIsTypedToo) {
  LoadOptions options;
  options.sets = {{"m.size", "big"}};
  validate(
      "facet: 1\nnodes:\n  s: {stage: io.frames, params: {path: x}}\n  m: {stage: "
      "filter.median, in: {depth: s.depth}}\n",
      options);
  EXPECT_EQ(single_error(diagnostics_),
            "<command line>: --set m.size=big: parameter 'size' of node 'm' (int): expected an "
            "integer, got 'big'");
}

TEST_F(ValidateGraph, UnknownPortsAndNodesSuggestNames) {
  validate(R"(facet: 1
nodes:
  source: {stage: io.frames, params: {path: x}}
  m: {stage: filter.median, in: {dpth: source.depth}}
  n: {stage: normals.cross, in: {depth: sorce.depth}}
  e: {stage: edges.angle, in: {normals: n.normal}}
)");
  EXPECT_EQ(diagnostics_.str(),
            "g.yaml:4:40: error: stage 'filter.median' of node 'm' has no input 'dpth'; did you "
            "mean 'depth'?\n"
            "g.yaml:4:3: error: node 'm': required input 'depth' (facet.DepthImage/1) of stage "
            "'filter.median' is not connected\n"
            "g.yaml:5:41: error: unknown node 'sorce' in input 'depth' of node 'n'; did you mean "
            "'source'?\n"
            "g.yaml:6:41: error: stage 'normals.cross' of node 'n' has no output 'normal'; did you "
            "mean 'normals'?\n");
}

TEST_F(ValidateGraph, TypeMismatchNamesBothEndsAndTypes) {
  validate(R"(facet: 1
nodes:
  s: {stage: io.frames, params: {path: x}}
  n: {stage: normals.cross, in: {depth: s.depth}}
  m: {stage: filter.median, in: {depth: n.normals}}
)");
  EXPECT_EQ(single_error(diagnostics_),
            "g.yaml:5:41: type mismatch: input 'm.depth' takes facet.DepthImage/1 but output "
            "'n.normals' gives facet.NormalImage/1");
}

TEST_F(ValidateGraph, UnconnectedRequiredInputIsReportedAtTheNode) {
  validate("facet: 1\nnodes:\n  e: {stage: edges.angle}\n");
  EXPECT_EQ(single_error(diagnostics_),
            "g.yaml:3:3: node 'e': required input 'normals' (facet.NormalImage/1) of stage "
            "'edges.angle' is not connected");
}

TEST_F(ValidateGraph, SourceTakesNoInputs) {
  validate(
      "facet: 1\nnodes:\n  a: {stage: io.frames, params: {path: x}}\n  b: {stage: io.frames, "
      "in: {depth: a.depth}, params: {path: y}}\n");
  EXPECT_EQ(single_error(diagnostics_),
            "g.yaml:4:25: node 'b': stage 'io.frames' is a source and takes no inputs");
}

TEST_F(ValidateGraph, CycleIsReportedWithItsPath) {
  validate(R"(facet: 1
nodes:
  a: {stage: filter.median, in: {depth: c.depth}}
  b: {stage: filter.median, in: {depth: a.depth}}
  c: {stage: filter.median, in: {depth: b.depth}}
  d: {stage: filter.median, in: {depth: d.depth}}
)");
  EXPECT_EQ(diagnostics_.str(),
            "g.yaml:3:41: error: cycle: a -> b -> c -> a\n"
            "g.yaml:6:41: error: cycle: d -> d\n");
}

TEST_F(ValidateGraph, CycleBehindAnAcyclicPrefixStartsAtItsEntry) {
  validate(R"(facet: 1
nodes:
  s: {stage: io.frames, params: {path: x}}
  e: {stage: edges.angle, in: {normals: n.normals, depth: m.depth}}
  m: {stage: filter.median, in: {depth: s.depth}}
  n: {stage: normals.cross, in: {depth: x.depth}}
  x: {stage: filter.median, in: {depth: y.depth}}
  y: {stage: filter.median, in: {depth: n.depth}}
)");
  EXPECT_EQ(diagnostics_.str(),
            "g.yaml:8:41: error: stage 'normals.cross' of node 'n' has no output 'depth'; its "
            "outputs are: normals\n"
            "g.yaml:6:41: error: cycle: n -> y -> x -> n\n");
}

constexpr const char* kOptionalWriter = R"(facet: 1
params: {output: ""}
nodes:
  source: {stage: io.frames, params: {path: rec}}
  write: {stage: io.depth, in: {depth: source.depth}, params: {dir: "${output}/depth"}, when: output}
)";

TEST_F(ValidateGraph, ANodeWhenItsParamIsSetAndLeftOutWhenItIsEmpty) {
  const ValidatedGraph without = validate(kOptionalWriter);
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  EXPECT_EQ(without.find("write"), nullptr);
  ASSERT_NE(without.find("source"), nullptr);

  LoadOptions options;
  options.params["output"] = "out";
  const ValidatedGraph with = validate(kOptionalWriter, options);
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  ASSERT_NE(with.find("write"), nullptr);
  EXPECT_EQ(with.find("write")->params.get_string("dir"), "out/depth");
}

TEST_F(ValidateGraph, ReadingALeftOutNodeIsAnErrorNamingItsParam) {
  const std::string yaml =
      std::string(kOptionalWriter) + "  after: {stage: filter.median, in: {depth: write.depth}}\n";
  validate(yaml);
  // The error is at the reference, the note at the `when:` that left the node out.
  EXPECT_EQ(single_error(diagnostics_),
            "g.yaml:6:45: node 'write' in input 'depth' of node 'after' is left out: graph "
            "parameter 'output' is empty");
  EXPECT_NE(diagnostics_.str().find("g.yaml:5:"), std::string::npos) << diagnostics_.str();
}

TEST_F(ValidateGraph, WhenMustNameAGraphParameter) {
  Diagnostics diagnostics;
  graph_test::load(R"(facet: 1
params: {output: ""}
nodes:
  source: {stage: io.frames, params: {path: rec}, when: outptu}
)",
                   diagnostics);
  EXPECT_EQ(single_error(diagnostics),
            "g.yaml:4:57: 'when' of node 'source' names no graph parameter: 'outptu'; did you "
            "mean 'output'?");
}

TEST_F(ValidateGraph, ReplacedStageWithOtherPortsIsRefusedWithANote) {
  LoadOptions options;
  options.variant = "points";
  validate(R"(facet: 1
nodes:
  s: {stage: io.frames, params: {path: x}}
  n: {stage: normals.cross, in: {depth: s.depth}}
  e: {stage: edges.angle, in: {normals: n.normals}}
variants:
  points: {replace: {n: {stage: normals.points}}}
)",
           options);
  EXPECT_EQ(diagnostics_.str(),
            "g.yaml:4:41: error: stage 'normals.points' of node 'n' has no input 'depth'; its "
            "inputs are: points\n"
            "g.yaml:7:33: note: variant 'points' replaced stage 'normals.cross' of node 'n' with "
            "'normals.points'; the replacement must provide the ports the graph uses, with the "
            "same types\n"
            "g.yaml:4:3: error: node 'n': required input 'points' (facet.PointImage/1) of stage "
            "'normals.points' is not connected\n"
            "g.yaml:7:33: note: variant 'points' replaced stage 'normals.cross' of node 'n' with "
            "'normals.points'; the replacement must provide the ports the graph uses, with the "
            "same types\n");
}

TEST_F(ValidateGraph, CompatibleReplacementValidates) {
  LoadOptions options;
  options.variant = "pca";
  const ValidatedGraph graph = validate(R"(facet: 1
nodes:
  s: {stage: io.frames, params: {path: x}}
  n: {stage: normals.cross, in: {depth: s.depth}, params: {radius: 3}}
  e: {stage: edges.angle, in: {normals: n.normals}}
variants:
  pca: {replace: {n: {stage: normals.pca, params: {window: 7}}}}
)",
                                        options);
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  EXPECT_EQ(graph.find("n")->stage->spec.name(), "normals.pca");
  EXPECT_EQ(graph.find("n")->params.get_int("window"), 7);
}

TEST_F(ValidateGraph, SkipsWhatTheLoaderAlreadyReported) {
  // A node without a stage and a malformed reference: one loader error each, nothing more.
  Diagnostics diagnostics;
  const GraphSpec graph = graph_test::load(
      "facet: 1\nnodes:\n  a: {params: {}}\n  m: {stage: filter.median, in: {depth: nodot}}\n",
      diagnostics);
  EXPECT_EQ(diagnostics.error_count(), 2) << diagnostics.str();
  validate_graph(graph, registry_, diagnostics);
  EXPECT_EQ(diagnostics.error_count(), 2) << diagnostics.str();
}

}  // namespace
}  // namespace facet
