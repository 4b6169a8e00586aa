// The graph-level `headline:` key: its two forms, which way is better, the errors of a malformed
// value or an unknown node, and how a derived graph (`extends:`) inherits or overrides it.

#include <fstream>
#include <string>

#include "graph_test_support.hpp"
#include "temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using graph_test::single_error;

// A graph with a scoring node, `headline:` appended as given.
std::string graph_with(const std::string& headline) {
  return "facet: 1\n"
         "nodes:\n"
         "  source: {stage: io.frames, params: {path: rec}}\n"
         "  score: {stage: eval.groundtruth, in: {labels: source.depth}}\n"
         "  shapes: {stage: shape.superquadric, in: {objects: source.depth}}\n" +
         headline + "\n";
}

GraphSpec load_clean(const std::string& yaml) {
  Diagnostics diagnostics;
  GraphSpec graph = graph_test::load(yaml, diagnostics);
  EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  return graph;
}

// The only error of loading `yaml`.
std::string error_of(const std::string& yaml) {
  Diagnostics diagnostics;
  graph_test::load(yaml, diagnostics);
  return single_error(diagnostics);
}

TEST(GraphHeadline, NoneUnlessTheGraphNamesOne) {
  EXPECT_FALSE(load_clean(graph_with("")).headline.has_value());
}

TEST(GraphHeadline, NodeDotMetricWithItsLocation) {
  const GraphSpec graph = load_clean(graph_with("headline: score.precision"));
  ASSERT_TRUE(graph.headline.has_value());
  EXPECT_EQ(graph.headline->node, "score");
  EXPECT_EQ(graph.headline->metric, "precision");
  EXPECT_EQ(graph.headline->key(), "score.precision");
  EXPECT_EQ(graph.headline->better, ScoreGoal::higher);
  EXPECT_EQ(format_location(graph.headline->where), "g.yaml:6:11");
}

TEST(GraphHeadline, WhichWayIsBetterFollowsTheMetricUnlessGiven) {
  // A time (`_ms`) and the over-segmentation count are better low without being told.
  EXPECT_EQ(load_clean(graph_with("headline: shapes.fit_ms")).headline->better, ScoreGoal::lower);
  EXPECT_EQ(load_clean(graph_with("headline: score.over_segmented")).headline->better,
            ScoreGoal::lower);
  const GraphSpec lower =
      load_clean(graph_with("headline: {metric: score.mean_iou, better: lower}"));
  EXPECT_EQ(lower.headline->key(), "score.mean_iou");
  EXPECT_EQ(lower.headline->better, ScoreGoal::lower);
  EXPECT_EQ(format_location(lower.headline->where), "g.yaml:6:20");
  EXPECT_EQ(
      load_clean(graph_with("headline: {metric: shapes.fit_ms, better: higher}")).headline->better,
      ScoreGoal::higher);
  // A count that describes the scene has no better way of its own, but may be given one.
  EXPECT_EQ(
      load_clean(graph_with("headline: {metric: score.segments, better: higher}")).headline->better,
      ScoreGoal::higher);
}

TEST(GraphHeadline, MalformedValuesAreErrorsAtTheirLine) {
  EXPECT_EQ(error_of(graph_with("headline: scoref")),
            "g.yaml:6:11: malformed headline 'scoref': expected 'node.metric', e.g. 'score.f'");
  EXPECT_EQ(error_of(graph_with("headline: 2score.f")),
            "g.yaml:6:11: malformed headline '2score.f': expected 'node.metric', e.g. 'score.f'");
  EXPECT_EQ(error_of(graph_with("headline: [score.f]")),
            "g.yaml:6:11: 'headline' must be 'node.metric' or a map {metric: node.metric, "
            "better: higher or lower}, got a list");
  EXPECT_EQ(error_of(graph_with("headline:")),
            "g.yaml:6:1: 'headline' must be 'node.metric' or a map {metric: node.metric, "
            "better: higher or lower}, got nothing");
  EXPECT_EQ(error_of(graph_with("headline: {metric: score.f, better: hihger}")),
            "g.yaml:6:37: 'better' of 'headline' must be 'higher' or 'lower', got 'hihger'; did "
            "you mean 'higher'?");
  EXPECT_EQ(error_of(graph_with("headline: {better: lower}")),
            "g.yaml:6:1: 'headline' has no 'metric' (the node and its metric, e.g. score.f)");
  EXPECT_EQ(error_of(graph_with("headline: {metric: score.f, bettr: lower}")),
            "g.yaml:6:29: unknown key 'bettr' in 'headline'; did you mean 'better'?");
  EXPECT_EQ(error_of(graph_with("headline: {metric: [score.f]}")),
            "g.yaml:6:20: 'metric' of 'headline' must be a scalar, got a list");
  EXPECT_EQ(error_of(graph_with("headline: score.segments")),
            "g.yaml:6:11: headline 'score.segments': the metric describes the scene or the run, "
            "neither way is better by default; say which with 'headline: {metric: "
            "score.segments, better: higher}' (or lower)");
}

TEST(GraphHeadline, UnknownNodeIsAnErrorWithASuggestion) {
  EXPECT_EQ(error_of(graph_with("headline: scroe.f")),
            "g.yaml:6:11: unknown node 'scroe' in 'headline'; did you mean 'score'?");
  EXPECT_EQ(error_of(graph_with("headline: {metric: nothing_like_it.f}")),
            "g.yaml:6:20: unknown node 'nothing_like_it' in 'headline'");
}

TEST(GraphHeadline, ANodeThatWhenLeavesOutIsStillAHeadline) {
  // The run then reports no such metric, and `facet compare` says so; the graph is valid.
  const GraphSpec graph = load_clean(
      "facet: 1\nparams: {truth: ''}\nnodes:\n"
      "  source: {stage: io.frames, params: {path: rec}}\n"
      "  score: {stage: eval.groundtruth, in: {labels: source.depth}, when: truth}\n"
      "headline: score.f\n");
  ASSERT_TRUE(graph.headline.has_value());
  EXPECT_EQ(graph.find_node("score"), nullptr);
}

class GraphHeadlineCompose : public testing::Test {
 protected:
  GraphHeadlineCompose() { write("base.yaml", graph_with("headline: score.f")); }

  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
  }

  GraphSpec load(const std::string& name) { return load_graph_file(dir_ / name, {}, diagnostics_); }

  std::string location(const std::string& name, int line, int column) const {
    return (dir_ / name).string() + ":" + std::to_string(line) + ":" + std::to_string(column);
  }

  test::TempDir dir_{"facet-headline"};
  Diagnostics diagnostics_;
};

TEST_F(GraphHeadlineCompose, ADerivedGraphInheritsTheBasesHeadline) {
  write("derived.yaml", "facet: 1\nextends: base.yaml\nset: {score.min_truth_pixels: 10}\n");
  const GraphSpec graph = load("derived.yaml");
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  ASSERT_TRUE(graph.headline.has_value());
  EXPECT_EQ(graph.headline->key(), "score.f");
  EXPECT_EQ(format_location(graph.headline->where), location("base.yaml", 6, 11));
}

TEST_F(GraphHeadlineCompose, ADerivedGraphOverridesIt) {
  write("derived.yaml",
        "facet: 1\nextends: base.yaml\nheadline: {metric: shapes.fit_ms, better: lower}\n");
  const GraphSpec graph = load("derived.yaml");
  ASSERT_FALSE(diagnostics_.has_errors()) << diagnostics_.str();
  ASSERT_TRUE(graph.headline.has_value());
  EXPECT_EQ(graph.headline->key(), "shapes.fit_ms");
  EXPECT_EQ(graph.headline->better, ScoreGoal::lower);
  EXPECT_EQ(format_location(graph.headline->where), location("derived.yaml", 3, 20));
}

TEST_F(GraphHeadlineCompose, AnInheritedHeadlineOfARemovedNodeIsAnError) {
  write("derived.yaml", "facet: 1\nextends: base.yaml\nremove: [score]\n");
  load("derived.yaml");
  EXPECT_EQ(single_error(diagnostics_),
            location("base.yaml", 6, 11) +
                ": node 'score' in 'headline' is left out: 'remove:' of " +
                (dir_ / "derived.yaml").string() +
                " takes it out; name another in that graph's 'headline:'");
  EXPECT_NE(diagnostics_.str().find(location("derived.yaml", 3, 10) +
                                    ": note: node 'score' removed here"),
            std::string::npos)
      << diagnostics_.str();
  // Naming another headline in the derived graph is the fix.
  Diagnostics fixed;
  write("fixed.yaml", "facet: 1\nextends: base.yaml\nremove: [score]\nheadline: shapes.fit_ms\n");
  EXPECT_EQ(load_graph_file(dir_ / "fixed.yaml", {}, fixed).headline->key(), "shapes.fit_ms");
  EXPECT_FALSE(fixed.has_errors()) << fixed.str();
}

}  // namespace
}  // namespace facet
