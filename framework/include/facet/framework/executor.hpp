#pragma once
// The sequential executor: the reference way to run a graph. One frame at a time, nodes in
// topological order, every stage call timed. Deterministic: the same graph on the same input gives
// the same output, which is what other executors are checked against.

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "facet/framework/validated_graph.hpp"

namespace facet {

// A failure while running a graph (stage construction, open, process, close). The message names
// the node, its stage and, during processing, the frame.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct NodeStats {
  std::string id;
  std::string stage;
  std::vector<double> call_ms;  // one sample per frame in which the node ran
  std::int64_t skipped = 0;     // frames in which a required input was empty
  std::map<std::string, std::vector<double>> metrics;
};

struct RunStats {
  std::int64_t frames = 0;
  std::vector<NodeStats> nodes;  // in execution order
  std::vector<double> frame_ms;  // wall time of each frame through the whole graph
};

struct FrameEvent {
  std::int64_t index;
  std::string stem;  // of the first source's depth output, when it has one
  double frame_ms;
};

struct RunOptions {
  std::int64_t max_frames = -1;  // < 0: until a source ends the stream
  // Called after every frame (progress display); may be empty.
  std::function<void(const FrameEvent&)> on_frame;
  // Receives stage warnings already prefixed with node and frame; may be empty (then dropped).
  std::function<void(const std::string&)> on_warning;
};

class SequentialExecutor {
 public:
  // Instantiates every stage from its validated parameters; throws RunError naming the node when
  // a stage's constructor fails. `graph` (and the Registry behind it) must outlive the executor.
  explicit SequentialExecutor(const ValidatedGraph& graph);
  ~SequentialExecutor();
  SequentialExecutor(const SequentialExecutor&) = delete;
  SequentialExecutor& operator=(const SequentialExecutor&) = delete;

  // Opens all stages, runs frames until a source ends the stream (or max_frames), closes all
  // stages (also when a stage fails). Throws RunError.
  RunStats run(const RunOptions& options = {});

 private:
  struct Node;
  const ValidatedGraph& graph_;
  std::vector<std::unique_ptr<Node>> nodes_;
};

}  // namespace facet
