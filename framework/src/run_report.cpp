#include "facet/framework/run_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>
#include <vector>

#include "facet/framework/json_writer.hpp"
#include "facet/framework/statistics.hpp"

namespace facet {
namespace {

// Where each node's calls and metric values of a frame are: frame → position in its vectors.
class FrameLookup {
 public:
  explicit FrameLookup(const std::vector<std::int64_t>& frames) {
    for (std::size_t i = 0; i < frames.size(); ++i)
      at_[frames[i]] = i;  // the last value of a frame, if a stage gave several
  }
  const std::size_t* find(std::int64_t frame) const {
    const auto it = at_.find(frame);
    return it == at_.end() ? nullptr : &it->second;
  }

 private:
  std::unordered_map<std::int64_t, std::size_t> at_;
};

struct NodeLookups {
  FrameLookup calls;
  std::map<std::string, FrameLookup> metrics;
};

// One entry per frame that went through the graph: its time, each stage's call time and every
// metric (eval stages' scores included), so that the worst frame is found without a rerun.
void write_per_frame(JsonWriter& json, const RunStats& stats) {
  std::vector<NodeLookups> lookups;
  for (const auto& node : stats.nodes) {
    NodeLookups lookup{FrameLookup(node.call_frames), {}};
    for (const auto& [name, frames] : node.metric_frames)
      lookup.metrics.emplace(name, FrameLookup(frames));
    lookups.push_back(std::move(lookup));
  }
  json.key("per_frame").begin_array();
  for (std::size_t k = 0; k < stats.frame_ms.size() && k < stats.frame_indices.size(); ++k) {
    const std::int64_t frame = stats.frame_indices[k];
    json.begin_object();
    json.key("frame").value(frame);
    json.key("stem").value(k < stats.frame_stems.size() ? stats.frame_stems[k] : std::string());
    json.key("ms").value(stats.frame_ms[k]);
    json.key("stages_ms").begin_object();
    for (std::size_t n = 0; n < stats.nodes.size(); ++n) {
      if (const std::size_t* call = lookups[n].calls.find(frame)) {
        json.key(stats.nodes[n].id).value(stats.nodes[n].call_ms[*call]);
      }
    }
    json.end_object();
    json.key("metrics").begin_object();
    for (std::size_t n = 0; n < stats.nodes.size(); ++n) {
      for (const auto& [name, lookup] : lookups[n].metrics) {
        if (const std::size_t* at = lookup.find(frame)) {
          json.key(stats.nodes[n].id + "." + name).value(stats.nodes[n].metrics.at(name)[*at]);
        }
      }
    }
    json.end_object();
    json.end_object();
  }
  json.end_array();
}

}  // namespace

void write_run_json(std::ostream& out, const RunStats& stats, const std::string& graph_name,
                    const std::string& variant) {
  JsonWriter json(out);
  json.begin_object();
  json.key("graph").value(graph_name);
  json.key("variant").value(variant);
  json.key("frames").value(stats.frames);
  json.key("stages").begin_object();
  for (const auto& node : stats.nodes) {
    json.key(node.id).begin_object();
    json.key("stage").value(node.stage);
    json.key("calls").value(static_cast<std::int64_t>(node.call_ms.size()));
    json.key("skipped").value(node.skipped);
    json.key("median_ms").value(median(node.call_ms));
    json.key("p95_ms").value(percentile(node.call_ms, 95.0));
    json.key("metrics").begin_object();
    for (const auto& [name, values] : node.metrics) {
      const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
      json.key(name).begin_object();
      json.key("mean").value(std::accumulate(values.begin(), values.end(), 0.0) /
                             static_cast<double>(values.size()));
      json.key("median").value(median(values));
      json.key("min").value(*lo);
      json.key("max").value(*hi);
      json.end_object();
    }
    json.end_object();
    json.end_object();
  }
  json.end_object();
  const double total_median = median(stats.frame_ms);
  json.key("total").begin_object();
  json.key("median_ms").value(total_median);
  json.key("p95_ms").value(percentile(stats.frame_ms, 95.0));
  json.key("fps").value(total_median > 0.0 ? 1000.0 / total_median : 0.0);
  json.key("throughput_fps").value(stats.throughput_fps());
  json.key("wall_ms").value(stats.wall_ms);
  json.key("dropped").value(stats.dropped);
  json.end_object();
  write_per_frame(json, stats);
  json.end_object();
}

void write_profile_table(std::ostream& out, const RunStats& stats) {
  std::size_t id_width = 5;
  std::size_t stage_width = 5;
  for (const auto& node : stats.nodes) {
    id_width = std::max(id_width, node.id.size());
    stage_width = std::max(stage_width, node.stage.size());
  }
  const double total_median = median(stats.frame_ms);
  out << fmt::format("{:<{}}  {:<{}}  {:>6}  {:>10}  {:>10}  {:>6}\n", "node", id_width, "stage",
                     stage_width, "calls", "median ms", "p95 ms", "share");
  for (const auto& node : stats.nodes) {
    const double node_median = median(node.call_ms);
    out << fmt::format("{:<{}}  {:<{}}  {:>6}  {:>10.3f}  {:>10.3f}  {:>5.1f}%\n", node.id,
                       id_width, node.stage, stage_width, node.call_ms.size(), node_median,
                       percentile(node.call_ms, 95.0),
                       total_median > 0.0 ? 100.0 * node_median / total_median : 0.0);
  }
  out << fmt::format("{:<{}}  {:>6}  {:>10.3f}  {:>10.3f}\n", "total (per frame)",
                     id_width + stage_width + 2, stats.frames, total_median,
                     percentile(stats.frame_ms, 95.0));
  out << fmt::format("throughput {:.1f} frames/s ({} frames in {:.0f} ms){}\n",
                     stats.throughput_fps(), stats.frames, stats.wall_ms,
                     stats.dropped > 0 ? fmt::format(", {} dropped", stats.dropped) : "");
}

}  // namespace facet
