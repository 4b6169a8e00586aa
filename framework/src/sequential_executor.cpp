#include <string>

#include "facet/framework/executor.hpp"
#include "node_runtime.hpp"
#include "stall_watchdog.hpp"

namespace facet {

struct SequentialExecutor::Node {
  detail::StageInstance instance;
  const ValidatedNode* spec = nullptr;
  std::unique_ptr<ProcessContext> ctx;
};

SequentialExecutor::SequentialExecutor(const ValidatedGraph& graph) : graph_(graph) {
  nodes_.reserve(graph.nodes.size());
  for (const auto& spec : graph.nodes) {
    auto node = std::make_unique<Node>();
    node->instance = detail::create_stage(spec);
    node->spec = &spec;
    node->ctx = std::make_unique<ProcessContext>(spec.stage->spec, spec.id);
    nodes_.push_back(std::move(node));
  }
}

SequentialExecutor::~SequentialExecutor() = default;

RunStats SequentialExecutor::run(const RunOptions& options) {
  detail::require_an_end(graph_, options);
  const auto run_start = detail::Clock::now();
  RunStats stats;
  stats.nodes = detail::node_stats_for(graph_);
  detail::StallWatchdog watchdog(options.stall_after, options.on_stall, 1);

  // Close whatever was opened, in reverse order, however run() is left.
  struct CloseGuard {
    std::vector<std::unique_ptr<Node>>& nodes;
    bool armed = true;
    ~CloseGuard() {
      if (!armed) return;
      for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
        // The first error is the one reported; a close failing after it is not news.
        (void)detail::close_stage((*it)->instance, *(*it)->spec);
      }
    }
  } guard{nodes_};

  for (auto& node : nodes_)
    detail::open_stage(node->instance, *node->spec);

  const auto outputs_of = [&](std::size_t i) {
    return std::span<const Packet>(nodes_[i]->ctx->outputs());
  };
  for (std::int64_t frame = 0; options.max_frames < 0 || frame < options.max_frames; ++frame) {
    if (options.stop_requested()) {
      stats.stopped = true;
      break;
    }
    const auto frame_start = detail::Clock::now();
    bool stream_ended = false;
    std::string stem;
    std::int64_t stream_frames = 0;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      Node& node = *nodes_[i];
      ProcessContext& ctx = *node.ctx;
      ctx.begin_frame(frame);
      if (!detail::gather_inputs(*node.spec, ctx, outputs_of)) {
        ++stats.nodes[i].skipped;
        continue;
      }

      const auto call_start = detail::Clock::now();
      watchdog.begin(0, *node.spec, frame, call_start);
      detail::call_stage(*node.instance.stage, ctx, *node.spec, stem);
      watchdog.end(0);
      const auto call_end = detail::Clock::now();
      detail::account_call(stats.nodes[i], ctx, detail::ms_between(call_start, call_end), options);
      if (options.record_calls) {
        stats.calls.push_back({i, frame, 0, detail::ms_between(run_start, call_start),
                               detail::ms_between(call_start, call_end)});
      }
      if (node.spec->stage->spec.is_source()) {
        if (ctx.at_end_of_stream()) {
          stream_ended = true;
          break;
        }
        const FrameInfo* info = stem.empty() ? detail::frame_of(ctx.outputs()) : nullptr;
        if (info != nullptr) {
          stem = info->stem;
          stream_frames = info->stream_frames;
        }
      }
    }
    if (stream_ended) break;
    const double frame_ms = detail::ms_between(frame_start, detail::Clock::now());
    stats.frame_ms.push_back(frame_ms);
    if (options.record_frames) {
      stats.frame_indices.push_back(frame);
      stats.frame_stems.push_back(stem);
    }
    ++stats.frames;
    if (options.on_frame) options.on_frame(FrameEvent{frame, stem, frame_ms, stream_frames});
  }

  // Close every stage even when one fails, then report the first failure: a sink that could not
  // flush its file must not go unnoticed.
  guard.armed = false;
  std::string first_close_error;
  for (auto it = nodes_.rbegin(); it != nodes_.rend(); ++it) {
    std::string error = detail::close_stage((*it)->instance, *(*it)->spec);
    if (first_close_error.empty()) first_close_error = std::move(error);
  }
  stats.wall_ms = detail::ms_between(run_start, detail::Clock::now());
  if (!first_close_error.empty()) throw RunError(first_close_error);
  return stats;
}

}  // namespace facet
