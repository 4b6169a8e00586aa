#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "graph_test_support.hpp"

namespace facet {
namespace {

using graph_test::find_param;
using graph_test::load;
using graph_test::single_error;

constexpr const char* kSmallGraph = R"(facet: 1
name: small
nodes:
  source: {stage: io.frames, params: {path: /data}}
  median:
    stage: filter.median
    in: {depth: source.depth}
    params: {size: 5}
)";

TEST(GraphLoader, ReadsNodesInFileOrderWithOneBasedLocations) {
  Diagnostics diagnostics;
  const GraphSpec graph = load(kSmallGraph, diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  EXPECT_EQ(graph.name, "small");
  ASSERT_EQ(graph.nodes.size(), 2u);
  EXPECT_EQ(graph.nodes[0].id, "source");
  EXPECT_FALSE(graph.nodes[0].inputs_where.has_value());
  const NodeSpec& median = graph.nodes[1];
  EXPECT_EQ(median.id, "median");
  EXPECT_EQ(median.stage, "filter.median");
  EXPECT_EQ(format_location(median.where), "g.yaml:5:3");
  EXPECT_EQ(format_location(median.stage_where), "g.yaml:6:12");
  ASSERT_EQ(median.inputs.size(), 1u);
  EXPECT_EQ(median.inputs[0].port, "depth");
  EXPECT_EQ(median.inputs[0].from_node, "source");
  EXPECT_EQ(median.inputs[0].from_port, "depth");
  EXPECT_EQ(format_location(median.inputs[0].where), "g.yaml:7:17");
  ASSERT_TRUE(median.inputs_where.has_value());
  const ParamSetting* size = find_param(median, "size");
  ASSERT_NE(size, nullptr);
  EXPECT_EQ(size->text, "5");
  EXPECT_EQ(format_location(size->where), "g.yaml:8:20");
  EXPECT_EQ(graph.find_node("median"), &graph.nodes[1]);
  EXPECT_EQ(graph.find_node("nope"), nullptr);
}

TEST(GraphLoader, NameDefaultsToTheFileStem) {
  Diagnostics diagnostics;
  const GraphSpec graph = load("facet: 1\nnodes: {a: {stage: x}}\n", diagnostics);
  EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  EXPECT_EQ(graph.name, "g");
}

TEST(GraphLoader, YamlCppAloneAcceptsDuplicateKeys) {
  // The reason for report_duplicate_keys: if this ever throws, the check could be simplified.
  EXPECT_NO_THROW(YAML::Load("a: 1\na: 2\n"));
}

TEST(GraphLoader, RejectsDuplicateKeysAtEveryLevel) {
  Diagnostics diagnostics;
  load(R"(facet: 1
nodes:
  a: {stage: x, params: {k: 1, k: 2}}
  a: {stage: y}
variants:
  v: {set: {a.k: 1, a.k: 2}}
facet: 1
)",
       diagnostics);
  const std::string text = diagnostics.str();
  EXPECT_EQ(diagnostics.error_count(), 4) << text;
  EXPECT_NE(text.find("g.yaml:3:32: error: duplicate key 'k' (first defined at line 3)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("g.yaml:4:3: error: duplicate key 'a' (first defined at line 3)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("g.yaml:6:21: error: duplicate key 'a.k'"), std::string::npos) << text;
  EXPECT_NE(text.find("g.yaml:7:1: error: duplicate key 'facet' (first defined at line 1)"),
            std::string::npos)
      << text;
}

TEST(GraphLoader, DuplicateNodeKeepsTheFirstDefinition) {
  Diagnostics diagnostics;
  const GraphSpec graph = load("facet: 1\nnodes:\n  a: {stage: x}\n  a: {stage: y}\n", diagnostics);
  ASSERT_EQ(graph.nodes.size(), 1u);
  EXPECT_EQ(graph.nodes[0].stage, "x");
}

TEST(GraphLoader, UnknownKeysGetSuggestions) {
  Diagnostics diagnostics;
  load(R"(facet: 1
node: {}
nodes:
  a: {stage: x, parms: {k: 1}}
variants:
  v: {sets: {a.k: 1}}
)",
       diagnostics);
  const std::string text = diagnostics.str();
  EXPECT_EQ(diagnostics.error_count(), 3) << text;
  EXPECT_NE(text.find("g.yaml:2:1: error: unknown key 'node' in the graph; did you mean 'nodes'?"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("g.yaml:4:17: error: unknown key 'parms' in node 'a'; did you mean "
                      "'params'?"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("g.yaml:6:7: error: unknown key 'sets' in variant 'v'; did you mean 'set'?"),
            std::string::npos)
      << text;
}

TEST(GraphLoader, UnknownKeyWithoutCloseMatchListsTheAllowedKeys) {
  Diagnostics diagnostics;
  load("facet: 1\nnodes: {a: {stage: x, colour: red}}\n", diagnostics);
  EXPECT_EQ(
      single_error(diagnostics),
      "g.yaml:2:23: unknown key 'colour' in node 'a'; expected one of: stage, in, params, when");
}

TEST(GraphLoader, RequiresFormatVersionOne) {
  {
    Diagnostics diagnostics;
    load("facet: 2\nnodes: {a: {stage: x}}\n", diagnostics);
    EXPECT_EQ(single_error(diagnostics),
              "g.yaml:1:8: unsupported graph format version '2'; this facet reads 'facet: 1'");
  }
  {
    Diagnostics diagnostics;
    load("nodes: {a: {stage: x}}\n", diagnostics);
    EXPECT_EQ(single_error(diagnostics),
              "g.yaml:1:1: missing key 'facet' (the format version: 'facet: 1')");
  }
}

TEST(GraphLoader, ReportsWrongYamlKinds) {
  Diagnostics diagnostics;
  load(R"(facet: 1
params: [a, b]
nodes:
  a: [stage, x]
  b: {stage: x, params: {k: {nested: 1}}, in: [a.out]}
)",
       diagnostics);
  const std::string text = diagnostics.str();
  EXPECT_EQ(diagnostics.error_count(), 4) << text;
  EXPECT_NE(text.find("g.yaml:2:9: error: 'params' must be a map, got a list"), std::string::npos)
      << text;
  EXPECT_NE(text.find("g.yaml:4:6: error: node 'a' must be a map, got a list"), std::string::npos)
      << text;
  EXPECT_NE(text.find("g.yaml:5:29: error: parameter 'k' must be a scalar, got a map"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("g.yaml:5:47: error: 'in' of node 'b' must be a map, got a list"),
            std::string::npos)
      << text;
}

TEST(GraphLoader, RejectsANonMapDocumentAndAnEmptyOne) {
  {
    Diagnostics diagnostics;
    load("- a\n- b\n", diagnostics);
    EXPECT_EQ(
        single_error(diagnostics),
        "g.yaml:1:1: a graph file must be a map (facet, name, params, nodes, ...), got a list");
  }
  {
    Diagnostics diagnostics;
    load("# nothing here\n", diagnostics);
    EXPECT_EQ(single_error(diagnostics), "g.yaml: the graph file is empty");
  }
}

TEST(GraphLoader, NodeWithoutStageAndInvalidIdsAreReported) {
  Diagnostics diagnostics;
  load("facet: 1\nnodes:\n  a: {params: {}}\n  2b: {stage: x}\n", diagnostics);
  const std::string text = diagnostics.str();
  EXPECT_EQ(diagnostics.error_count(), 2) << text;
  EXPECT_NE(text.find("g.yaml:3:3: error: node 'a' has no 'stage'"), std::string::npos) << text;
  EXPECT_NE(text.find("g.yaml:4:3: error: invalid node id '2b'"), std::string::npos) << text;
}

TEST(GraphLoader, RejectsMalformedPortReferences) {
  for (const std::string ref : {"source", "source.", ".depth", "source.depth.x", "so urce.depth"}) {
    Diagnostics diagnostics;
    load("facet: 1\nnodes:\n  a: {stage: x, in: {depth: \"" + ref + "\"}}\n", diagnostics);
    EXPECT_EQ(single_error(diagnostics),
              "g.yaml:3:29: malformed reference '" + ref +
                  "' for input 'depth' of node 'a': expected 'node.port'")
        << ref;
  }
}

TEST(GraphLoader, ReportsYamlSyntaxErrorsAtTheirMark) {
  Diagnostics diagnostics;
  const GraphSpec graph = load("facet: 1\nnodes:\n  a: {stage: x\n  b: 1\n", diagnostics);
  ASSERT_EQ(diagnostics.error_count(), 1) << diagnostics.str();
  const Diagnostic& error = diagnostics.all()[0];
  EXPECT_EQ(error.where.file, "g.yaml");
  EXPECT_GE(error.where.line, 3);  // 1-based: yaml-cpp's mark is at least on line index 2
  EXPECT_GE(error.where.column, 1);
  EXPECT_FALSE(error.message.empty());
  EXPECT_TRUE(graph.nodes.empty());
}

// An alias that contains itself overflowed the stack of the duplicate-key walk, and nested
// aliases (billion laughs) made it exponential: aliases are refused before the document is built.
TEST(GraphLoader, RefusesYamlAliasesAtTheirMark) {
  std::ostringstream laughs;
  laughs << "facet: 1\na0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n";
  for (int i = 1; i < 10; ++i) {
    laughs << 'a' << i << ": &a" << i << " [*a" << i - 1;
    for (int k = 1; k < 9; ++k)
      laughs << ", *a" << i - 1;
    laughs << "]\n";
  }
  const std::pair<std::string, std::string> cases[] = {
      {"facet: 1\ndescription: &x [*x]\nnodes: {a: {stage: x}}\n", "g.yaml:2:"},
      {laughs.str() + "nodes: {a: {stage: x}}\n", "g.yaml:3:"},
      {"facet: 1\nparams: {p: &v 3}\nnodes: {a: {stage: x, params: {q: *v}}}\n", "g.yaml:3:"},
  };
  for (const auto& [yaml, where] : cases) {
    Diagnostics diagnostics;
    const GraphSpec graph = load(yaml, diagnostics);
    const std::string error = single_error(diagnostics);
    EXPECT_EQ(error.rfind(where, 0), 0U) << error;
    EXPECT_NE(error.find("YAML aliases (*name) are not allowed"), std::string::npos) << error;
    EXPECT_TRUE(graph.nodes.empty());
  }
}

// Found by the graph fuzz target: on this stream yaml-cpp's parser reports a next document
// forever, and the alias check looped over documents. The load ends, with an error.
TEST(GraphLoader, AStrayCommaAndAByteThatIsNotUtf8EndWithAnError) {
  Diagnostics diagnostics;
  const GraphSpec graph = load(std::string(",acetcac: e\xa0", 12), diagnostics);
  EXPECT_NE(single_error(diagnostics).find("holds no YAML value"), std::string::npos);
  EXPECT_TRUE(graph.nodes.empty());
}

TEST(GraphLoader, MissingFileIsOneDiagnosticNamingIt) {
  Diagnostics diagnostics;
  load_graph_file("no/such/graph.yaml", {}, diagnostics);
  EXPECT_EQ(single_error(diagnostics), "no/such/graph.yaml: cannot read graph file: no such file");
}

TEST(GraphLoader, DirectoryIsNotAGraphFile) {
  Diagnostics diagnostics;
  load_graph_file(testing::TempDir(), {}, diagnostics);
  EXPECT_NE(single_error(diagnostics).find("it is a directory"), std::string::npos);
}

class GraphFileTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::path(testing::TempDir()) /
        ("facet_graph_loader_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir_ / "graphs");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = dir_ / "graphs" / name;
    std::ofstream(path) << text;
    return path;
  }

  std::filesystem::path dir_;
};

TEST_F(GraphFileTest, GraphDirAndPluginPathsAreRelativeToTheFile) {
  const auto file = write("g.yaml", R"(facet: 1
params: {input: "${graph_dir}/../data"}
plugins: {paths: [../plugins, /opt/facet/plugins, "${graph_dir}/more"]}
nodes:
  source: {stage: io.frames, params: {path: "${input}/mosd", where: "${graph_dir}"}}
)");
  Diagnostics diagnostics;
  const GraphSpec graph = load_graph_file(file, {}, diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  const auto dir = std::filesystem::absolute(dir_ / "graphs").lexically_normal();
  EXPECT_EQ(graph.graph_dir, dir);
  EXPECT_EQ(graph.file, file);
  ASSERT_EQ(graph.plugin_paths.size(), 3u);
  EXPECT_EQ(graph.plugin_paths[0], (dir / "../plugins").lexically_normal());
  EXPECT_EQ(graph.plugin_paths[1], std::filesystem::path("/opt/facet/plugins"));
  EXPECT_EQ(graph.plugin_paths[2], dir / "more");
  EXPECT_EQ(graph.params.at("input"), dir.generic_string() + "/../data");
  EXPECT_EQ(find_param(graph.nodes[0], "path")->text, dir.generic_string() + "/../data/mosd");
  EXPECT_EQ(find_param(graph.nodes[0], "where")->text, dir.generic_string());
}

TEST(GraphParams, SubstituteInStagesParamsAndInputs) {
  Diagnostics diagnostics;
  const GraphSpec graph = load(R"(facet: 1
params: {family: filter, out: results, from: source}
nodes:
  source: {stage: io.frames}
  f: {stage: "${family}.median", in: {depth: "${from}.depth"}, params: {dir: "${out}/${out}", n: 3}}
)",
                               diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  const NodeSpec& f = graph.nodes[1];
  EXPECT_EQ(f.stage, "filter.median");
  EXPECT_EQ(f.inputs[0].from_node, "source");
  EXPECT_EQ(find_param(f, "dir")->text, "results/results");
  EXPECT_EQ(find_param(f, "n")->text, "3");
  EXPECT_EQ(graph.params.at("out"), "results");
}

TEST(GraphParams, CommandLineOverridesTheDefault) {
  LoadOptions options;
  options.params["out"] = "elsewhere";
  Diagnostics diagnostics;
  const GraphSpec graph = load(
      "facet: 1\nparams: {out: results}\nnodes: {w: {stage: io.depth, params: {dir: "
      "\"${out}/d\"}}}\n",
      diagnostics, options);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  EXPECT_EQ(graph.params.at("out"), "elsewhere");
  EXPECT_EQ(find_param(graph.nodes[0], "dir")->text, "elsewhere/d");
}

TEST(GraphParams, UnknownCommandLineParamIsAnErrorWithSuggestion) {
  LoadOptions options;
  options.params["ouptut"] = "x";
  Diagnostics diagnostics;
  load("facet: 1\nparams: {input: a, output: b}\nnodes: {a: {stage: x}}\n", diagnostics, options);
  EXPECT_EQ(single_error(diagnostics),
            "<command line>: --param ouptut=x: unknown graph parameter 'ouptut'; did you mean "
            "'output'?");
}

TEST(GraphParams, UndefinedReferenceIsReportedAtTheScalar) {
  Diagnostics diagnostics;
  load("facet: 1\nparams: {input: a}\nnodes:\n  a: {stage: x, params: {p: \"${inptu}/x\"}}\n",
       diagnostics);
  EXPECT_EQ(single_error(diagnostics),
            "g.yaml:4:29: undefined graph parameter '${inptu}'; did you mean 'input'?");
}

// `--param output=` made '${output}/labels' the folder '/labels': as root, facet wrote there.
TEST(GraphParams, AnEmptyOrRootParamThatWouldPutAPathAtTheRootIsAnError) {
  for (const std::string value : {"", "/", "//"}) {
    LoadOptions options;
    options.params["output"] = value;
    Diagnostics diagnostics;
    load(
        "facet: 1\nparams: {output: out}\nnodes:\n  a: {stage: x, params: {dir: "
        "\"${output}/labels\"}}\n",
        diagnostics, options);
    const std::string error = single_error(diagnostics);
    EXPECT_NE(error.find("g.yaml:4:31: graph parameter 'output' is "), std::string::npos) << error;
    EXPECT_NE(error.find("'${output}/labels' a path at the filesystem root"), std::string::npos)
        << error;
  }
  // Empty elsewhere in a value, or not followed by a folder, stays allowed.
  LoadOptions options;
  options.params["output"] = "";
  Diagnostics diagnostics;
  const auto graph = load(
      "facet: 1\nparams: {output: out}\nnodes:\n  a: {stage: x, params: {dir: \"a${output}/b\", "
      "e: \"${output}\"}}\n",
      diagnostics, options);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  EXPECT_EQ(find_param(graph.nodes[0], "dir")->text, "a/b");
}

TEST(GraphParams, UnterminatedReferenceIsReported) {
  Diagnostics diagnostics;
  load("facet: 1\nnodes:\n  a: {stage: x, params: {p: \"${input\"}}\n", diagnostics);
  EXPECT_EQ(single_error(diagnostics), "g.yaml:3:29: unterminated '${' in '${input'");
}

TEST(GraphParams, GraphDirCannotBeRedefined) {
  Diagnostics diagnostics;
  load("facet: 1\nparams: {graph_dir: /x}\nnodes: {a: {stage: x}}\n", diagnostics);
  EXPECT_EQ(single_error(diagnostics),
            "g.yaml:2:21: graph parameter 'graph_dir' is built in and cannot be redefined");
}

TEST(GraphSets, CommandLineSetOverridesOrAddsAParam) {
  LoadOptions options;
  options.sets = {{"m.size", "7"}, {"m.extra", "on"}, {"m.size", "9"}};
  Diagnostics diagnostics;
  const GraphSpec graph = load("facet: 1\nnodes: {m: {stage: filter.median, params: {size: 3}}}\n",
                               diagnostics, options);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  const NodeSpec& m = graph.nodes[0];
  ASSERT_EQ(m.params.size(), 2u);
  EXPECT_EQ(find_param(m, "size")->text, "9");  // applied in order: the last one wins
  EXPECT_EQ(find_param(m, "size")->where.file, kCommandLineFile);
  EXPECT_EQ(find_param(m, "size")->where.line, 0);
  EXPECT_EQ(find_param(m, "extra")->text, "on");
}

TEST(GraphSets, UnknownNodeOrMalformedSetIsAnError) {
  LoadOptions options;
  options.sets = {{"meddian.size", "7"}, {"size", "3"}};
  Diagnostics diagnostics;
  load("facet: 1\nnodes: {median: {stage: filter.median}}\n", diagnostics, options);
  EXPECT_EQ(diagnostics.str(),
            "<command line>: error: --set meddian.size=7: unknown node 'meddian'; did you mean "
            "'median'?\n"
            "<command line>: error: --set size=3: expected 'node.param=value'\n");
}

TEST(GraphLoader, ReportsEverythingAtOnce) {
  Diagnostics diagnostics;
  load(R"(facet: 3
nme: x
nodes:
  a: {stage: x, in: {d: nodot}, params: {p: "${nope}"}}
  a: {stage: y}
)",
       diagnostics);
  EXPECT_EQ(diagnostics.error_count(), 5) << diagnostics.str();
}

}  // namespace
}  // namespace facet
