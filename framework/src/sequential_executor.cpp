#include <algorithm>
#include <chrono>
#include <exception>
#include <string>

#include "facet/framework/executor.hpp"
#include "facet/types/images.hpp"

namespace facet {

// The library member is declared first so that it is destroyed last: a stage's code lives in its
// plugin, which must stay loaded until the stage is gone.
struct SequentialExecutor::Node {
  std::shared_ptr<const void> library;
  const ValidatedNode* spec = nullptr;
  std::unique_ptr<Stage> stage;
  std::unique_ptr<ProcessContext> ctx;
  bool opened = false;
};

namespace {

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

std::string describe(const ValidatedNode& node) {
  return "node '" + node.id + "' (" + node.stage->spec.name() + ")";
}

std::string frame_stem(const ProcessContext& ctx) {
  for (const Packet& out : ctx.outputs()) {
    if (const auto* header = out.get_if<DepthImage>()) return header->frame.stem;
  }
  return {};
}

}  // namespace

SequentialExecutor::SequentialExecutor(const ValidatedGraph& graph) : graph_(graph) {
  nodes_.reserve(graph.nodes.size());
  for (const auto& spec : graph.nodes) {
    auto node = std::make_unique<Node>();
    node->library = spec.stage->library;
    node->spec = &spec;
    try {
      node->stage = spec.stage->spec.factory()(spec.params);
    } catch (const std::exception& e) {
      throw RunError(describe(spec) + ": could not be created: " + e.what());
    }
    node->ctx = std::make_unique<ProcessContext>(spec.stage->spec, spec.id);
    nodes_.push_back(std::move(node));
  }
}

SequentialExecutor::~SequentialExecutor() = default;

RunStats SequentialExecutor::run(const RunOptions& options) {
  const bool has_source = std::any_of(nodes_.begin(), nodes_.end(), [](const auto& node) {
    return node->spec->stage->spec.is_source();
  });
  if (!has_source && options.max_frames < 0) {
    throw RunError("graph '" + graph_.name +
                   "' has no source stage to end the stream; give a frame count");
  }
  RunStats stats;
  stats.nodes.reserve(nodes_.size());
  for (const auto& node : nodes_) {
    stats.nodes.push_back({node->spec->id, node->spec->stage->spec.name(), {}, 0, {}});
  }

  // Close whatever was opened, in reverse order, however run() is left.
  struct CloseGuard {
    std::vector<std::unique_ptr<Node>>& nodes;
    bool armed = true;
    ~CloseGuard() {
      if (!armed) return;
      for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
        if ((*it)->opened) {
          (*it)->opened = false;
          try {
            (*it)->stage->close();
          } catch (...) {  // NOLINT(bugprone-empty-catch): the first error is the one reported
          }
        }
      }
    }
  } guard{nodes_};

  for (auto& node : nodes_) {
    try {
      node->stage->open(OpenContext{node->spec->id});
      node->opened = true;
    } catch (const std::exception& e) {
      throw RunError(describe(*node->spec) + ": could not be opened: " + e.what());
    }
  }

  for (std::int64_t frame = 0; options.max_frames < 0 || frame < options.max_frames; ++frame) {
    const auto frame_start = Clock::now();
    bool stream_ended = false;
    std::string stem;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      Node& node = *nodes_[i];
      ProcessContext& ctx = *node.ctx;
      ctx.begin_frame(frame);

      // Gather inputs; a stage whose required input is empty this frame does not run.
      bool runnable = true;
      const auto& input_specs = node.spec->stage->spec.inputs();
      auto inputs = ctx.inputs();
      for (std::size_t port = 0; port < inputs.size(); ++port) {
        const auto& connection = node.spec->inputs[port];
        inputs[port] = connection
                           ? nodes_[connection->from_node]->ctx->outputs()[connection->from_port]
                           : Packet();
        if (inputs[port].empty() && input_specs[port].required) runnable = false;
      }
      if (!runnable) {
        ++stats.nodes[i].skipped;
        continue;
      }

      const auto call_start = Clock::now();
      try {
        node.stage->process(ctx);
      } catch (const std::exception& e) {
        throw RunError(describe(*node.spec) + ", frame " + std::to_string(frame) +
                       (stem.empty() ? "" : " (" + stem + ")") + ": " + e.what());
      }
      stats.nodes[i].call_ms.push_back(elapsed_ms(call_start));

      for (const auto& warning : ctx.warnings()) {
        if (options.on_warning) {
          options.on_warning("warning: node '" + node.spec->id + "', frame " +
                             std::to_string(frame) + ": " + warning);
        }
      }
      for (const auto& metric : ctx.metrics()) {
        stats.nodes[i].metrics[metric.name].push_back(metric.value);
      }
      if (node.spec->stage->spec.is_source()) {
        if (ctx.at_end_of_stream()) {
          stream_ended = true;
          break;
        }
        if (stem.empty()) stem = frame_stem(ctx);
      }
    }
    if (stream_ended) break;
    const double frame_ms = elapsed_ms(frame_start);
    stats.frame_ms.push_back(frame_ms);
    ++stats.frames;
    if (options.on_frame) options.on_frame(FrameEvent{frame, stem, frame_ms});
  }

  // Close every stage even when one fails, then report the first failure: a sink that could not
  // flush its file must not go unnoticed.
  guard.armed = false;
  std::string first_close_error;
  for (auto it = nodes_.rbegin(); it != nodes_.rend(); ++it) {
    Node& node = **it;
    node.opened = false;
    try {
      node.stage->close();
    } catch (const std::exception& e) {
      if (first_close_error.empty()) {
        first_close_error = describe(*node.spec) + ": could not be closed: " + e.what();
      }
    }
  }
  if (!first_close_error.empty()) throw RunError(first_close_error);
  return stats;
}

}  // namespace facet
