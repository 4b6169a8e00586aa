#include "node_runtime.hpp"

#include <algorithm>
#include <exception>

namespace facet::detail {

std::string describe(const ValidatedNode& node) {
  return "node '" + node.id + "' (" + node.stage->spec.name() + ")";
}

StageInstance create_stage(const ValidatedNode& node) {
  StageInstance instance;
  instance.library = node.stage->library;
  try {
    instance.stage = node.stage->spec.factory()(node.params);
  } catch (const std::exception& e) {
    throw RunError(describe(node) + ": could not be created: " + e.what());
  }
  return instance;
}

void open_stage(StageInstance& instance, const ValidatedNode& node) {
  try {
    instance.stage->open(OpenContext{node.id});
    instance.opened = true;
  } catch (const std::exception& e) {
    throw RunError(describe(node) + ": could not be opened: " + e.what());
  }
}

std::string close_stage(StageInstance& instance, const ValidatedNode& node) noexcept {
  if (!instance.opened) return {};
  instance.opened = false;
  try {
    instance.stage->close();
  } catch (const std::exception& e) {
    return describe(node) + ": could not be closed: " + e.what();
  } catch (...) {
    return describe(node) + ": could not be closed";
  }
  return {};
}

void require_an_end(const ValidatedGraph& graph, const RunOptions& options) {
  const bool has_source = std::any_of(graph.nodes.begin(), graph.nodes.end(), [](const auto& node) {
    return node.stage->spec.is_source();
  });
  if (!has_source && options.max_frames < 0) {
    throw RunError("graph '" + graph.name +
                   "' has no source stage to end the stream; give a frame count");
  }
}

std::vector<NodeStats> node_stats_for(const ValidatedGraph& graph) {
  std::vector<NodeStats> stats;
  stats.reserve(graph.nodes.size());
  for (const auto& node : graph.nodes) {
    NodeStats node_stats;
    node_stats.id = node.id;
    node_stats.stage = node.stage->spec.name();
    stats.push_back(std::move(node_stats));
  }
  return stats;
}

void call_stage(Stage& stage, ProcessContext& ctx, const ValidatedNode& node,
                std::string_view stem) {
  try {
    stage.process(ctx);
  } catch (const std::exception& e) {
    throw RunError(describe(node) + ", frame " + std::to_string(ctx.frame_index()) +
                   (stem.empty() ? "" : " (" + std::string(stem) + ")") + ": " + e.what());
  }
}

void account_call(NodeStats& stats, const ProcessContext& ctx, double call_ms,
                  const RunOptions& options) {
  stats.call_ms.push_back(call_ms);
  if (options.record_frames) stats.call_frames.push_back(ctx.frame_index());
  if (options.on_warning) {
    for (const auto& warning : ctx.warnings()) {
      options.on_warning("warning: node '" + ctx.node_id() + "', frame " +
                         std::to_string(ctx.frame_index()) + ": " + warning);
    }
  }
  for (const auto& metric : ctx.metrics()) {
    stats.metrics[metric.name].push_back(metric.value);
    if (options.record_frames) stats.metric_frames[metric.name].push_back(ctx.frame_index());
  }
}

const FrameInfo* frame_of(std::span<const Packet> outputs) {
  for (const Packet& out : outputs) {
    if (const FrameHeader* header = out.header()) return &header->frame;
  }
  return nullptr;
}

}  // namespace facet::detail
