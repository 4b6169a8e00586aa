// Merging variants for A/B comparison: what is shared, what is renamed, and how inputs follow.
#include <gtest/gtest.h>

#include <facet/framework/graph_merge.hpp>
#include <string>

namespace facet {
namespace {

constexpr const char* kGraph = R"(facet: 1
name: merge
params:
  output: out
nodes:
  source: {stage: io.frames, params: {path: data}}
  median: {stage: filter.median, in: {depth: source.depth}, params: {size: 3}}
  points: {stage: convert.points, in: {depth: median.depth}}
  normals: {stage: normals.cross, in: {depth: median.depth}, params: {radius: 2}}
  edges: {stage: edges.max, in: {normals: normals.normals}}
  patches: {stage: grow.surfaces, in: {edges: edges.edges, points: points.points}}
  sink: {stage: io.labels, in: {labels: patches.patches}, params: {dir: "${output}/patches"}}
variants:
  r1: {set: {normals.radius: 1}}
  r2: {set: {normals.radius: 2}}
  r1_again: {set: {normals.radius: 1}}
  pca: {replace: {normals: {stage: normals.pca, params: {window: 5}}}}
  median5: {set: {median.size: 5}}
)";

VariantGraph load(const std::string& variant, const std::string& output = "out") {
  Diagnostics diagnostics;
  LoadOptions options;
  options.variant = variant;
  options.params["output"] = output;
  GraphSpec spec = load_graph_text(kGraph, "merge.yaml", options, diagnostics);
  EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  return {variant.empty() ? "base" : variant, std::move(spec)};
}

const NodeSpec& node(const MergedGraph& merged, const std::string& id) {
  const NodeSpec* found = merged.spec.find_node(id);
  if (found == nullptr) throw std::runtime_error("no node '" + id + "' in the merged graph");
  return *found;
}

std::string input_of(const NodeSpec& node, const std::string& port) {
  for (const auto& input : node.inputs) {
    if (input.port == port) return input.from_node + "." + input.from_port;
  }
  return "";
}

TEST(MergeVariants, IdenticalNodesAreSharedAndDifferingOnesRenamedDownstream) {
  const MergedGraph merged = merge_variants({load("r1"), load("pca")});
  // Upstream of the difference: one node for both variants, under its own id.
  EXPECT_TRUE(merged.is_shared("source"));
  EXPECT_TRUE(merged.is_shared("median"));
  EXPECT_TRUE(merged.is_shared("points"));
  // The difference and everything fed by it: one copy per variant.
  for (const char* id : {"normals", "edges", "patches", "sink"}) {
    EXPECT_EQ(merged.spec.find_node(id), nullptr) << id;
    EXPECT_FALSE(merged.is_shared(std::string(id) + "@r1")) << id;
    EXPECT_NE(merged.spec.find_node(std::string(id) + "@pca"), nullptr) << id;
  }
  EXPECT_EQ(node(merged, "normals@pca").stage, "normals.pca");
  EXPECT_EQ(input_of(node(merged, "normals@r1"), "depth"), "median.depth");
  EXPECT_EQ(input_of(node(merged, "edges@pca"), "normals"), "normals@pca.normals");
  EXPECT_EQ(input_of(node(merged, "patches@r1"), "edges"), "edges@r1.edges");
  EXPECT_EQ(input_of(node(merged, "patches@r1"), "points"), "points.points");
  EXPECT_EQ(merged.variants[1].node_ids.at("patches"), "patches@pca");
  EXPECT_EQ(merged.variants[0].node_ids.at("median"), "median");
  EXPECT_EQ(merged.spec.nodes.size(), 3u + 2u * 4u);
}

TEST(MergeVariants, ChangingAnUpstreamNodeRenamesEverythingBelowIt) {
  const MergedGraph merged = merge_variants({load("r2"), load("median5")});
  EXPECT_TRUE(merged.is_shared("source"));
  for (const char* id : {"median", "points", "normals", "edges", "patches", "sink"}) {
    EXPECT_EQ(merged.spec.find_node(id), nullptr) << id;
    EXPECT_NE(merged.spec.find_node(std::string(id) + "@r2"), nullptr) << id;
    EXPECT_NE(merged.spec.find_node(std::string(id) + "@median5"), nullptr) << id;
  }
  EXPECT_EQ(input_of(node(merged, "points@median5"), "depth"), "median@median5.depth");
}

TEST(MergeVariants, VariantsThatAgreeShareOneVersion) {
  const MergedGraph merged = merge_variants({load("r1"), load("r2"), load("r1_again")});
  // r1 and r1_again have the same normals: one node for the two, one for r2.
  EXPECT_NE(merged.spec.find_node("normals@r1+r1_again"), nullptr);
  EXPECT_NE(merged.spec.find_node("normals@r2"), nullptr);
  EXPECT_TRUE(merged.is_shared("normals@r1+r1_again"));
  EXPECT_EQ(merged.users.at("edges@r1+r1_again"), (std::vector<std::string>{"r1", "r1_again"}));
  EXPECT_EQ(merged.variants[2].node_ids.at("edges"), "edges@r1+r1_again");
}

TEST(MergeVariants, IdenticalGraphsMergeIntoOne) {
  const MergedGraph merged = merge_variants({load("r2"), load("")});
  // No variant is the file as written, which has radius 2 too.
  EXPECT_EQ(merged.spec.nodes.size(), 7u);
  for (const auto& spec_node : merged.spec.nodes)
    EXPECT_TRUE(merged.is_shared(spec_node.id)) << spec_node.id;
}

TEST(MergeVariants, PerVariantNodesAreNeverShared) {
  MergeOptions options;
  options.keep_per_variant = [](const NodeSpec& n) { return n.stage == "io.labels"; };
  const MergedGraph merged = merge_variants({load("r2", "out"), load("", "out")}, options);
  EXPECT_TRUE(merged.is_shared("patches"));
  EXPECT_NE(merged.spec.find_node("sink@r2"), nullptr);
  EXPECT_NE(merged.spec.find_node("sink@base"), nullptr);
  EXPECT_EQ(input_of(node(merged, "sink@r2"), "labels"), "patches.patches");
}

TEST(MergeVariants, DifferentOutputFoldersMakeSinksDiffer) {
  const MergedGraph merged = merge_variants({load("r2", "out/a"), load("", "out/b")});
  EXPECT_TRUE(merged.is_shared("patches"));
  EXPECT_EQ(node(merged, "sink@r2").params.at(0).text, "out/a/patches");
  EXPECT_EQ(merged.spec.variant, "r2,base");
}

TEST(MergeVariants, OneVariantKeepsItsIds) {
  const MergedGraph merged = merge_variants({load("pca")});
  EXPECT_NE(merged.spec.find_node("normals"), nullptr);
  EXPECT_EQ(node(merged, "normals").stage, "normals.pca");
}

TEST(MergeVariants, RejectsNoVariantsAndDuplicates) {
  EXPECT_THROW(merge_variants({}), std::invalid_argument);
  EXPECT_THROW(merge_variants({load("r1"), load("r1")}), std::invalid_argument);
}

}  // namespace
}  // namespace facet
