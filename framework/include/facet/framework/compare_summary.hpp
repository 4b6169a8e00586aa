#pragma once
// The numbers of an A/B comparison: one run of a merged graph (graph_merge.hpp) summarised per
// variant — the per-frame time of the nodes each variant runs (its own and the shared ones),
// per-stage medians and 95th percentiles, and the metrics its stages reported.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "facet/framework/executor.hpp"
#include "facet/framework/graph_merge.hpp"
#include "facet/framework/score_goal.hpp"
#include "facet/framework/sweep_summary.hpp"
#include "facet/framework/validated_graph.hpp"

namespace facet {

// What a node does in a frame's time: sources read, sinks write (or score), the rest process.
enum class NodeRole { source, process, sink };

struct StageTiming {
  std::string node;       // id in the graph file
  std::string merged_id;  // id in the merged graph (node@variant when not shared)
  std::string stage;
  NodeRole role = NodeRole::process;
  bool shared = false;    // run once for several variants
  std::size_t calls = 0;  // timed calls (after warm-up)
  double median_ms = 0.0;
  double p95_ms = 0.0;
};

struct MetricSummary {
  std::string node;  // id in the graph file
  std::string name;
  std::size_t count = 0;  // frames that reported it (warm-up frames included)
  double mean = 0.0;
  double median = 0.0;
  double min = 0.0;
  double max = 0.0;
  // Every value with its frame, in frame order: which frame scored worst, without a rerun.
  std::vector<std::int64_t> frames = {};
  std::vector<double> values = {};
};

struct VariantSummary {
  std::string name;
  std::vector<double> frame_ms;  // per timed frame: sum of the variant's processing nodes
  double median_ms = 0.0;
  double p95_ms = 0.0;
  std::vector<StageTiming> stages;  // in execution order
  std::vector<MetricSummary> metrics;

  // The summary of metric `metric_name` from the first of the variant's nodes that reports it
  // (in execution order), or nullptr.
  const MetricSummary* find_metric(const std::string& metric_name) const;
  // The same from node `node` (its id in the graph file), or nullptr.
  const MetricSummary* find_metric(const std::string& node, const std::string& metric_name) const;
};

// The metric reports lead with when the graph names none: eval.groundtruth's F-measure.
inline constexpr const char* kDefaultHeadlineMetric = "f";

// The metric the reports lead with: the graph's `headline:`, or by default the F ("f") of the
// first node that reports one.
struct Headline {
  std::string node;  // id in the graph file
  std::string metric;
  ScoreGoal goal = ScoreGoal::higher;  // higher or lower
  bool from_graph = false;             // named by the graph's `headline:`
  bool reported = false;               // some variant reported it
  SourceLocation where;                // of the graph's `headline:`, when from_graph

  std::string key() const { return node + "." + metric; }
  // How reports name it: "F" for F, else the metric's name.
  std::string label() const;
  // The variant's value (mean over frames), or nullptr when it reported none.
  const MetricSummary* of(const VariantSummary& variant) const;
  // The variant whose value is best by `goal` (the first of equals), or nothing.
  std::optional<std::size_t> best(const std::vector<VariantSummary>& variants) const;
};

struct CompareSummary {
  std::string graph;
  std::int64_t frames = 0;               // frames run
  std::int64_t warmup = 0;               // leading frames left out of the timing
  std::vector<std::string> frame_stems;  // of each frame run, from its source ("" when none)
  std::vector<VariantSummary> variants;
  // None when the graph names no headline and no variant reports an F.
  std::optional<Headline> headline;
  // Set when the variants are the points of a parameter sweep (one per point, in its order).
  std::optional<SweepSummary> sweep;
};

// `stats` must come from running `graph`, validated from `merged.spec`, with
// RunOptions::record_calls set (the calls tell each sample's frame). Frames below `warmup` are
// left out of every time; metrics keep every frame. The headline is `merged.spec.headline`.
CompareSummary summarize_comparison(const MergedGraph& merged, const ValidatedGraph& graph,
                                    const RunStats& stats, std::int64_t warmup);

const char* role_name(NodeRole role);

}  // namespace facet
