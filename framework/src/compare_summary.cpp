#include "facet/framework/compare_summary.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "facet/framework/statistics.hpp"

namespace facet {
namespace {

NodeRole role_of(const ValidatedNode& node) {
  if (node.stage == nullptr) return NodeRole::process;
  if (node.stage->spec.inputs().empty()) return NodeRole::source;
  if (node.stage->spec.outputs().empty()) return NodeRole::sink;
  return NodeRole::process;
}

MetricSummary summarize_metric(const std::string& node, const std::string& name,
                               const std::vector<double>& values) {
  MetricSummary summary;
  summary.node = node;
  summary.name = name;
  summary.count = values.size();
  if (values.empty()) return summary;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  summary.mean =
      std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  summary.median = median(values);
  summary.min = *lo;
  summary.max = *hi;
  return summary;
}

// The graph's headline, or else the F of the first node that reports one in any variant.
std::optional<Headline> headline_of(const GraphSpec& graph,
                                    const std::vector<VariantSummary>& variants) {
  std::optional<Headline> headline;
  if (graph.headline) {
    const HeadlineSpec& named = *graph.headline;
    headline = Headline{named.node, named.metric, named.better, true, false, named.where};
  } else {
    for (const auto& variant : variants) {
      const MetricSummary* f = variant.find_metric(kDefaultHeadlineMetric);
      if (f == nullptr) continue;
      headline = Headline{f->node, f->name, ScoreGoal::higher, false, false, {}};
      break;
    }
    if (!headline) return std::nullopt;
  }
  headline->reported = std::any_of(variants.begin(), variants.end(), [&](const auto& variant) {
    return headline->of(variant) != nullptr;
  });
  return headline;
}

}  // namespace

std::string Headline::label() const {
  return metric == kDefaultHeadlineMetric ? "F" : metric;
}

const MetricSummary* Headline::of(const VariantSummary& variant) const {
  return variant.find_metric(node, metric);
}

std::optional<std::size_t> Headline::best(const std::vector<VariantSummary>& variants) const {
  std::optional<std::size_t> best;
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const MetricSummary* value = of(variants[v]);
    if (value == nullptr) continue;
    const double best_mean = best ? of(variants[*best])->mean : 0.0;
    if (!best || (goal == ScoreGoal::lower ? value->mean < best_mean : value->mean > best_mean)) {
      best = v;
    }
  }
  return best;
}

const char* role_name(NodeRole role) {
  switch (role) {
    case NodeRole::source:
      return "source";
    case NodeRole::sink:
      return "sink";
    case NodeRole::process:
      break;
  }
  return "process";
}

const MetricSummary* VariantSummary::find_metric(const std::string& metric_name) const {
  const auto it = std::find_if(metrics.begin(), metrics.end(),
                               [&](const MetricSummary& m) { return m.name == metric_name; });
  return it == metrics.end() ? nullptr : &*it;
}

const MetricSummary* VariantSummary::find_metric(const std::string& node,
                                                 const std::string& metric_name) const {
  const auto it = std::find_if(metrics.begin(), metrics.end(), [&](const MetricSummary& m) {
    return m.node == node && m.name == metric_name;
  });
  return it == metrics.end() ? nullptr : &*it;
}

CompareSummary summarize_comparison(const MergedGraph& merged, const ValidatedGraph& graph,
                                    const RunStats& stats, std::int64_t warmup) {
  CompareSummary summary;
  summary.graph = merged.spec.name;
  summary.frames = stats.frames;
  summary.warmup = std::min(warmup, stats.frames);
  summary.frame_stems = stats.frame_stems;

  // Every timed call by node index (of stats.nodes) and frame.
  std::map<std::string, std::size_t> stats_index;
  for (std::size_t i = 0; i < stats.nodes.size(); ++i)
    stats_index[stats.nodes[i].id] = i;
  std::vector<std::map<std::int64_t, double>> call_ms(stats.nodes.size());
  for (const auto& call : stats.calls) {
    if (call.frame >= summary.warmup && call.node < call_ms.size()) {
      call_ms[call.node][call.frame] += call.duration_ms;
    }
  }

  for (const auto& variant : merged.variants) {
    VariantSummary result;
    result.name = variant.name;
    std::map<std::int64_t, double> frame_ms;
    for (std::int64_t frame = summary.warmup; frame < stats.frames; ++frame)
      frame_ms[frame] = 0.0;
    // In execution order, which is the graph's.
    for (const auto& node : graph.nodes) {
      const auto original = std::find_if(variant.node_ids.begin(), variant.node_ids.end(),
                                         [&](const auto& ids) { return ids.second == node.id; });
      if (original == variant.node_ids.end()) continue;
      const auto index = stats_index.find(node.id);
      if (index == stats_index.end()) continue;
      StageTiming timing;
      timing.node = original->first;
      timing.merged_id = node.id;
      timing.stage = node.stage != nullptr ? node.stage->spec.name() : "";
      timing.role = role_of(node);
      timing.shared = merged.is_shared(node.id);
      std::vector<double> samples;
      for (const auto& [frame, ms] : call_ms[index->second]) {
        samples.push_back(ms);
        if (timing.role == NodeRole::process) frame_ms[frame] += ms;
      }
      timing.calls = samples.size();
      timing.median_ms = median(samples);
      timing.p95_ms = percentile(samples, 95.0);
      result.stages.push_back(timing);
      const NodeStats& node_stats = stats.nodes[index->second];
      for (const auto& [name, values] : node_stats.metrics) {
        MetricSummary metric = summarize_metric(original->first, name, values);
        metric.values = values;
        if (const auto frames = node_stats.metric_frames.find(name);
            frames != node_stats.metric_frames.end()) {
          metric.frames = frames->second;
        }
        result.metrics.push_back(std::move(metric));
      }
    }
    for (const auto& [frame, ms] : frame_ms)
      result.frame_ms.push_back(ms);
    result.median_ms = median(result.frame_ms);
    result.p95_ms = percentile(result.frame_ms, 95.0);
    summary.variants.push_back(std::move(result));
  }
  summary.headline = headline_of(merged.spec, summary.variants);
  return summary;
}

}  // namespace facet
