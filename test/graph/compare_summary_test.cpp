// The per-variant summary of a merged run, on hand-made run statistics: which calls count for
// which variant, warm-up frames, shared stages, metrics.
#include <gtest/gtest.h>

#include <facet/framework/compare_report.hpp>
#include <facet/framework/compare_summary.hpp>
#include <facet/types/images.hpp>
#include <sstream>

namespace facet {
namespace {

StageEntry entry(const std::string& name, bool has_input, bool has_output) {
  StageSpec spec(name, "test stage");
  if (has_input) spec.input<DepthImage>("depth", "in");
  if (has_output) spec.output<DepthImage>("depth", "out");
  return StageEntry{nullptr, std::move(spec), nullptr};
}

// source -> filter (shared) -> work@a / work@b -> sink@a / sink@b
class CompareSummaryTest : public ::testing::Test {
 protected:
  CompareSummaryTest()
      : source_(entry("test.source", false, true)),
        process_(entry("test.process", true, true)),
        sink_(entry("test.sink", true, false)) {
    merged_.spec.name = "g";
    merged_.variants = {
        {"a", {{"source", "source"}, {"filter", "filter"}, {"work", "work@a"}, {"sink", "sink@a"}}},
        {"b",
         {{"source", "source"}, {"filter", "filter"}, {"work", "work@b"}, {"sink", "sink@b"}}}};
    merged_.users = {{"source", {"a", "b"}}, {"filter", {"a", "b"}}, {"work@a", {"a"}},
                     {"work@b", {"b"}},      {"sink@a", {"a"}},      {"sink@b", {"b"}}};
    const std::vector<std::pair<std::string, const StageEntry*>> nodes = {
        {"source", &source_},  {"filter", &process_}, {"work@a", &process_},
        {"work@b", &process_}, {"sink@a", &sink_},    {"sink@b", &sink_}};
    for (const auto& [id, stage] : nodes) {
      ValidatedNode node;
      node.id = id;
      node.stage = stage;
      graph_.nodes.push_back(node);
      NodeStats node_stats;
      node_stats.id = id;
      node_stats.stage = stage->spec.name();
      stats_.nodes.push_back(node_stats);
    }
    // Three frames; node i takes (i + 1) * (frame + 1) ms, so every sum is known.
    stats_.frames = 3;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      for (std::int64_t frame = 0; frame < 3; ++frame) {
        stats_.calls.push_back(
            {i, frame, 0, 0.0, static_cast<double>((i + 1) * static_cast<std::size_t>(frame + 1))});
      }
    }
    stats_.nodes[4].metrics["f"] = {0.5, 0.7, 0.9};
    stats_.nodes[5].metrics["f"] = {0.1, 0.2};
  }

  StageEntry source_;
  StageEntry process_;
  StageEntry sink_;
  MergedGraph merged_;
  ValidatedGraph graph_;
  RunStats stats_;
};

TEST_F(CompareSummaryTest, FrameTimeIsTheSumOfTheVariantsProcessingNodes) {
  const CompareSummary summary = summarize_comparison(merged_, graph_, stats_, 1);
  ASSERT_EQ(summary.variants.size(), 2u);
  EXPECT_EQ(summary.warmup, 1);
  // Variant a: filter (2 ms per frame unit) + work@a (3); frames 1 and 2 (x2, x3).
  EXPECT_EQ(summary.variants[0].frame_ms, (std::vector<double>{10.0, 15.0}));
  // Variant b: filter (2) + work@b (4).
  EXPECT_EQ(summary.variants[1].frame_ms, (std::vector<double>{12.0, 18.0}));
  EXPECT_DOUBLE_EQ(summary.variants[1].median_ms, 15.0);
}

TEST_F(CompareSummaryTest, StagesKeepTheirFileIdsRolesAndSharing) {
  const CompareSummary summary = summarize_comparison(merged_, graph_, stats_, 0);
  const auto& stages = summary.variants[1].stages;
  ASSERT_EQ(stages.size(), 4u);
  EXPECT_EQ(stages[0].node, "source");
  EXPECT_EQ(stages[0].role, NodeRole::source);
  EXPECT_TRUE(stages[1].shared);
  EXPECT_EQ(stages[2].node, "work");
  EXPECT_EQ(stages[2].merged_id, "work@b");
  EXPECT_FALSE(stages[2].shared);
  EXPECT_EQ(stages[2].calls, 3u);
  EXPECT_DOUBLE_EQ(stages[2].median_ms, 8.0);  // 4, 8, 12
  EXPECT_EQ(stages[3].role, NodeRole::sink);
  // No warm-up: three frames of filter + work@b = 6, 12, 18.
  EXPECT_EQ(summary.variants[1].frame_ms, (std::vector<double>{6.0, 12.0, 18.0}));
}

TEST_F(CompareSummaryTest, MetricsBelongToTheVariantThatReportedThem) {
  const CompareSummary summary = summarize_comparison(merged_, graph_, stats_, 2);
  const MetricSummary* a = summary.variants[0].find_metric("f");
  const MetricSummary* b = summary.variants[1].find_metric("f");
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(a->node, "sink");
  EXPECT_EQ(a->count, 3u);  // warm-up frames count for metrics
  EXPECT_DOUBLE_EQ(a->mean, 0.7);
  EXPECT_DOUBLE_EQ(b->mean, 0.15);
  EXPECT_DOUBLE_EQ(b->max, 0.2);
  EXPECT_EQ(summary.variants[0].find_metric("missing"), nullptr);
}

TEST_F(CompareSummaryTest, WithoutAGraphHeadlineTheReportsLeadWithF) {
  const CompareSummary summary = summarize_comparison(merged_, graph_, stats_, 1);
  ASSERT_TRUE(summary.headline.has_value());
  EXPECT_EQ(summary.headline->key(), "sink.f");
  EXPECT_EQ(summary.headline->label(), "F");
  EXPECT_FALSE(summary.headline->from_graph);
  EXPECT_TRUE(summary.headline->reported);
  EXPECT_EQ(summary.headline->best(summary.variants), std::optional<std::size_t>(0));
  std::ostringstream table;
  write_compare_table(table, summary);
  EXPECT_NE(table.str().find("\nbest sink.f (the headline, higher is better): a 0.7\n"),
            std::string::npos)
      << table.str();
  // Nothing reports an F: no headline at all.
  stats_.nodes[4].metrics.clear();
  stats_.nodes[5].metrics.clear();
  EXPECT_FALSE(summarize_comparison(merged_, graph_, stats_, 1).headline.has_value());
}

TEST_F(CompareSummaryTest, TheGraphsHeadlineAndItsWayDecideTheBest) {
  stats_.nodes[4].metrics["fit_ms"] = {3.0, 3.0};
  stats_.nodes[5].metrics["fit_ms"] = {2.0, 1.0};
  merged_.spec.headline = HeadlineSpec{"sink", "fit_ms", ScoreGoal::lower, {"g.yaml", 9, 11}};
  const CompareSummary summary = summarize_comparison(merged_, graph_, stats_, 1);
  ASSERT_TRUE(summary.headline.has_value());
  EXPECT_EQ(summary.headline->key(), "sink.fit_ms");
  EXPECT_EQ(summary.headline->label(), "fit_ms");
  EXPECT_TRUE(summary.headline->from_graph);
  EXPECT_TRUE(summary.headline->reported);
  // Lower is better: b (1.5 ms) beats a (3 ms), although a has the better F.
  EXPECT_EQ(summary.headline->best(summary.variants), std::optional<std::size_t>(1));
  std::ostringstream json;
  write_compare_json(json, summary);
  EXPECT_NE(json.str().find(R"("headline": {
    "metric": "sink.fit_ms",
    "better": "lower",
    "from_graph": true,
    "reported": true,
    "best": "b"
  })"),
            std::string::npos)
      << json.str().substr(0, 600);

  // Named but reported by no variant: kept, and said to be missing; no best.
  merged_.spec.headline->metric = "fit_sm";
  const CompareSummary missing = summarize_comparison(merged_, graph_, stats_, 1);
  ASSERT_TRUE(missing.headline.has_value());
  EXPECT_FALSE(missing.headline->reported);
  EXPECT_FALSE(missing.headline->best(missing.variants).has_value());
  std::ostringstream table;
  write_compare_table(table, missing);
  EXPECT_NE(table.str().find("\nheadline sink.fit_sm: no variant reported it\n"), std::string::npos)
      << table.str();
}

TEST_F(CompareSummaryTest, WarmupLongerThanTheRunLeavesNoTimedFrame) {
  const CompareSummary summary = summarize_comparison(merged_, graph_, stats_, 10);
  EXPECT_EQ(summary.warmup, 3);
  EXPECT_TRUE(summary.variants[0].frame_ms.empty());
  EXPECT_EQ(summary.variants[0].stages[1].calls, 0u);
}

TEST_F(CompareSummaryTest, ReportsNameEveryVariant) {
  const CompareSummary summary = summarize_comparison(merged_, graph_, stats_, 1);
  std::ostringstream table;
  std::ostringstream json;
  std::ostringstream csv;
  write_compare_table(table, summary);
  write_compare_json(json, summary);
  write_compare_csv(csv, summary);
  EXPECT_NE(table.str().find("  work "), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("  sink.f "), std::string::npos) << table.str();
  EXPECT_NE(json.str().find("\"merged_id\": \"work@b\""), std::string::npos);
  EXPECT_NE(csv.str().find("a,total,,,frame_ms,,2,12.5,"), std::string::npos) << csv.str();
  EXPECT_NE(csv.str().find("b,stage,filter,test.process,call_ms,yes,2,"), std::string::npos);
  EXPECT_NE(csv.str().find("b,metric,sink,,f,,2,0.15,,0.15"), std::string::npos) << csv.str();
}

}  // namespace
}  // namespace facet
