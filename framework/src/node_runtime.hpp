#pragma once
// What every executor does with a node, however it schedules frames: create, open and close its
// stage, gather its inputs for a frame, call it, and account for the call (time, metrics,
// warnings). Keeping this in one place keeps the executors' error messages and statistics
// identical, which is what lets one executor be checked against the other.

#include <chrono>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/framework/executor.hpp"
#include "facet/stage.hpp"
#include "facet/types/frame.hpp"

namespace facet::detail {

using Clock = std::chrono::steady_clock;

inline double ms_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// "node 'median' (filter.median)"
std::string describe(const ValidatedNode& node);

// One instance of a node's stage. The library member is declared first so that it is destroyed
// last: a stage's code lives in its plugin, which must stay loaded until the stage is gone.
struct StageInstance {
  std::shared_ptr<const void> library;
  std::unique_ptr<Stage> stage;
  bool opened = false;
};

// Throws RunError naming the node when the stage's constructor fails.
StageInstance create_stage(const ValidatedNode& node);
// Throws RunError naming the node when open() fails.
void open_stage(StageInstance& instance, const ValidatedNode& node);
// Closes an opened instance; returns the error message naming the node, or empty.
std::string close_stage(StageInstance& instance, const ValidatedNode& node) noexcept;

// A graph needs a source (which ends the stream) or a frame count; throws RunError otherwise.
void require_an_end(const ValidatedGraph& graph, const RunOptions& options);

// One empty NodeStats per node, in the graph's order.
std::vector<NodeStats> node_stats_for(const ValidatedGraph& graph);

// Fills ctx's inputs from the producers' outputs for the same frame; `outputs_of(i)` returns the
// outputs (std::span<const Packet>) of node i. Returns false when a required input is empty: the
// node does not run this frame.
template <class OutputsOf>
bool gather_inputs(const ValidatedNode& node, ProcessContext& ctx, OutputsOf&& outputs_of) {
  bool runnable = true;
  const auto& input_specs = node.stage->spec.inputs();
  auto inputs = ctx.inputs();
  for (std::size_t port = 0; port < inputs.size(); ++port) {
    const auto& connection = node.inputs[port];
    inputs[port] = connection ? outputs_of(connection->from_node)[connection->from_port] : Packet();
    if (inputs[port].empty() && input_specs[port].required) runnable = false;
  }
  return runnable;
}

// Calls process(); any exception becomes a RunError naming node, stage, frame and file stem.
void call_stage(Stage& stage, ProcessContext& ctx, const ValidatedNode& node,
                std::string_view stem);

// Adds one call's time and metrics to `stats` and hands its warnings, prefixed with node and
// frame, to options.on_warning.
void account_call(NodeStats& stats, const ProcessContext& ctx, double call_ms,
                  const RunOptions& options);

// The frame of a source's first output that carries one (its stem and how long the stream is),
// or nothing.
const FrameInfo* frame_of(std::span<const Packet> outputs);

}  // namespace facet::detail
