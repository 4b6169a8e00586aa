// Graph composition (`extends:` a base graph file, with `remove:`, `replace:`, `set:` and added
// nodes) and the command line's `--replace node=stage`.

#include <facet/framework/validated_graph.hpp>
#include <fstream>
#include <string>

#include "graph_test_support.hpp"
#include "temp_dir.hpp"
#include "test_stages.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using graph_test::find_param;
using graph_test::single_error;

constexpr const char* kBase = R"(facet: 1
name: base
params:
  input: "${graph_dir}/data"
  output: out/base
nodes:
  source: {stage: io.frames, params: {path: "${input}", fps: 15}}
  median: {stage: filter.median, in: {depth: source.depth}, params: {size: 5}}
  normals: {stage: normals.cross, in: {depth: median.depth}}
  write: {stage: io.depth, in: {depth: median.depth}, params: {dir: "${output}/depth"}}
outputs: {depth: median.depth, normals: normals.normals}
variants:
  big: {set: {median.size: 7}}
  angle: {set: {normals.radius: 3}}
)";

class GraphCompose : public testing::Test {
 protected:
  GraphCompose() {
    graph_test::add_test_stages(registry_);
    write("base/base.yaml", kBase);
  }

  void write(const std::string& name, const std::string& text) const {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name) << text;
  }

  GraphSpec load(const std::string& name, const LoadOptions& options = {}) {
    return load_graph_file(dir_ / name, options, diagnostics_);
  }

  std::string location(const std::string& name, int line, int column) const {
    return (dir_ / name).string() + ":" + std::to_string(line) + ":" + std::to_string(column);
  }

  test::TempDir dir_{"facet-compose"};
  Registry registry_;
  Diagnostics diagnostics_;
};

TEST_F(GraphCompose, ADerivedGraphEditsAndAddsToItsBase) {
  write("derived.yaml", R"(facet: 1
name: derived
extends: base/base.yaml
params: {output: out/derived, show: all}
remove: [write]
replace:
  normals: {stage: normals.pca}
set: {median.size: 3}
nodes:
  edges: {stage: edges.angle, in: {normals: normals.normals}, params: {threshold: 1}}
)");
  const GraphSpec graph = load("derived.yaml");
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  EXPECT_EQ(graph.name, "derived");
  // The base's params with the derived defaults; ${graph_dir} in the base is the base's folder.
  EXPECT_EQ(graph.params.at("output"), "out/derived");
  EXPECT_EQ(graph.params.at("show"), "all");
  EXPECT_EQ(graph.params.at("input"), (dir_.path() / "base").generic_string() + "/data");
  std::vector<std::string> ids;
  for (const auto& node : graph.nodes)
    ids.push_back(node.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"source", "median", "normals", "edges"}));
  EXPECT_EQ(graph.find_node("normals")->stage, "normals.pca");
  EXPECT_TRUE(graph.find_node("normals")->params.empty());  // the new stage's defaults
  EXPECT_EQ(find_param(*graph.find_node("median"), "size")->text, "3");
  // The base's graph outputs and variants come along.
  ASSERT_EQ(graph.outputs.size(), 2u);
  EXPECT_EQ(graph.variants, (std::vector<std::string>{"big", "angle"}));
  const ValidatedGraph validated = validate_graph(graph, registry_, diagnostics_);
  EXPECT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  EXPECT_NE(validated.find("edges"), nullptr);
}

TEST_F(GraphCompose, WhatRemovedNodesWereInIsDroppedAndReadingThemIsAnError) {
  write("derived.yaml", R"(facet: 1
extends: base/base.yaml
remove: normals
nodes:
  edges: {stage: edges.angle, in: {normals: normals.normals}}
)");
  const GraphSpec graph = load("derived.yaml");
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  EXPECT_EQ(graph.name, "derived");  // the derived file's stem, not the base's name
  // The output and the variant that needed `normals` are gone with it.
  ASSERT_EQ(graph.outputs.size(), 1u);
  EXPECT_EQ(graph.outputs[0].name, "depth");
  EXPECT_EQ(graph.variants, (std::vector<std::string>{"big"}));
  validate_graph(graph, registry_, diagnostics_);
  EXPECT_EQ(single_error(diagnostics_),
            location("derived.yaml", 5, 45) +
                ": node 'normals' in input 'normals' of node 'edges' is left out: 'remove:' of " +
                (dir_ / "derived.yaml").string() + " takes it out");
  EXPECT_NE(diagnostics_.str().find(location("derived.yaml", 3, 9) +
                                    ": note: node 'normals' removed here"),
            std::string::npos)
      << diagnostics_.str();
}

TEST_F(GraphCompose, AProblemInTheBaseNamesBothFiles) {
  write("broken/base.yaml", R"(facet: 1
nodes:
  source: {stage: io.frames, params: {path: rec}}
  median: {stage: filter.median, in: {depth: source.depth}, params: {size: 5}, colour: red}
)");
  write("derived.yaml", "facet: 1\nextends: broken/base.yaml\n");
  load("derived.yaml");
  const std::string text = diagnostics_.str();
  EXPECT_NE(text.find(location("broken/base.yaml", 4, 80) + ": error: unknown key 'colour'"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(location("derived.yaml", 2, 10) + ": note: in the base graph of " +
                      (dir_ / "derived.yaml").string()),
            std::string::npos)
      << text;
}

TEST_F(GraphCompose, RemovedVariantsAreNotInherited) {
  write("derived.yaml", "facet: 1\nextends: base/base.yaml\nremove_variants: [angle]\n");
  EXPECT_EQ(load("derived.yaml").variants, (std::vector<std::string>{"big"}));
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  write("typo.yaml", "facet: 1\nextends: base/base.yaml\nremove_variants: [bgi]\n");
  load("typo.yaml");
  EXPECT_EQ(single_error(diagnostics_),
            location("typo.yaml", 3, 19) +
                ": unknown variant 'bgi' in 'remove_variants' of the base graph; did you mean "
                "'big'?");
}

TEST_F(GraphCompose, EditsNamingNoNodeOfTheBaseSuggestOne) {
  write("derived.yaml", R"(facet: 1
extends: base/base.yaml
remove: [writ]
set: {medain.size: 3}
nodes:
  median: {stage: filter.median, in: {depth: source.depth}}
)");
  load("derived.yaml");
  const std::string text = diagnostics_.str();
  EXPECT_EQ(diagnostics_.error_count(), 3) << text;
  EXPECT_NE(text.find(location("derived.yaml", 3, 10) +
                      ": error: unknown node 'writ' in 'remove' of the base graph; did you mean "
                      "'write'?"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("unknown node 'medain' in 'set' of the base graph; did you mean 'median'?"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(location("derived.yaml", 6, 3) +
                      ": error: node 'median' is already in the base graph"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(location("base/base.yaml", 8, 3) + ": note: the base graph's node 'median'"),
            std::string::npos)
      << text;
}

TEST_F(GraphCompose, CyclesMissingBasesAndEditsWithoutABaseAreErrors) {
  write("a.yaml", "facet: 1\nextends: b.yaml\n");
  write("b.yaml", "facet: 1\nextends: ./a.yaml\n");
  load("a.yaml");
  EXPECT_NE(diagnostics_.str().find("graph extends cycle"), std::string::npos)
      << diagnostics_.str();

  Diagnostics missing;
  write("c.yaml", "facet: 1\nextends: nowhere.yaml\n");
  load_graph_file(dir_ / "c.yaml", {}, missing);
  EXPECT_EQ(single_error(missing), location("c.yaml", 2, 10) + ": cannot read base graph '" +
                                       (dir_ / "nowhere.yaml").string() + "': no such file");

  Diagnostics no_base;
  graph_test::load("facet: 1\nnodes: {a: {stage: io.frames}}\nremove: [a]\n", no_base);
  EXPECT_EQ(single_error(no_base),
            "g.yaml:3:1: 'remove' edits the nodes of a base graph, but this graph has no "
            "'extends: BASE.yaml'");
}

TEST_F(GraphCompose, CommandLineReplaceGivesANodeAnotherStageBeforeSet) {
  LoadOptions options;
  options.replaces = {{"normals", "normals.pca"}};
  options.sets = {{"normals.window", "5"}};
  const GraphSpec graph = load("base/base.yaml", options);
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  const NodeSpec* normals = graph.find_node("normals");
  EXPECT_EQ(normals->stage, "normals.pca");
  ASSERT_EQ(normals->params.size(), 1u);
  EXPECT_EQ(normals->params[0].name, "window");
  EXPECT_EQ(normals->inputs.size(), 1u);  // the inputs stay

  Diagnostics unknown;
  LoadOptions typo;
  typo.replaces = {{"normls", "normals.pca"}};
  load_graph_file(dir_ / "base/base.yaml", typo, unknown);
  EXPECT_EQ(single_error(unknown),
            "<command line>: --replace normls=normals.pca: unknown node 'normls'; did you mean "
            "'normals'?");
}

}  // namespace
}  // namespace facet
