#pragma once
// Running a graph. Two executors share these types:
// - SequentialExecutor, the reference: one frame at a time, nodes in topological order. The same
//   graph on the same input gives the same output, which is what other executors are checked
//   against.
// - PipelinedExecutor (pipelined_executor.hpp): several frames in flight on a fixed pool of
//   threads, each stage run as its declared Concurrency allows; it writes the same outputs.

#include <atomic>
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
  std::vector<double> call_ms;  // one sample per frame in which the node ran, in frame order
  std::vector<std::int64_t> call_frames;  // the frame of each call_ms sample (record_frames)
  std::int64_t skipped = 0;               // frames in which a required input was empty
  std::map<std::string, std::vector<double>> metrics;
  std::map<std::string, std::vector<std::int64_t>> metric_frames;  // each value's (record_frames)
};

// One stage call, for traces: which node ran which frame on which thread, and when.
struct CallRecord {
  std::size_t node = 0;  // index into RunStats::nodes
  std::int64_t frame = 0;
  int thread = 0;         // 0 = the thread that called run(), then the pool's workers 1..n-1
  double start_ms = 0.0;  // since the run started
  double duration_ms = 0.0;
};

struct RunStats {
  std::int64_t frames = 0;       // frames that went through the whole graph
  std::vector<NodeStats> nodes;  // in execution order
  // Latency of each frame, in frame order: from its first source call to the end of its last
  // stage call (with one frame at a time this is the frame's wall time).
  std::vector<double> frame_ms;
  std::vector<std::int64_t> frame_indices;  // the frame of each frame_ms sample (record_frames)
  std::vector<std::string> frame_stems;     // and its source's stem ("" when it has none)
  double wall_ms = 0.0;           // the whole run, from opening the first stage to closing the last
  std::int64_t dropped = 0;       // frames a `latest` source replaced before they were processed
  bool stopped = false;           // RunOptions::stop ended the run before the stream ended
  std::vector<CallRecord> calls;  // only with RunOptions::record_calls, in no particular order

  // Frames per second over the whole run (throughput), 0 before any frame.
  double throughput_fps() const {
    return wall_ms > 0.0 ? 1000.0 * static_cast<double>(frames) / wall_ms : 0.0;
  }
};

struct FrameEvent {
  std::int64_t index;
  std::string stem;  // of the first source's depth output, when it has one
  double frame_ms;
  std::int64_t stream_frames = 0;  // frames that source will deliver; 0 when it does not know
};

// A stage call that has been running for longer than RunOptions::stall_after.
struct StallReport {
  std::string node;   // node id
  std::string stage;  // stage name
  std::int64_t frame;
  double held_ms;       // how long the call has been running
  std::string message;  // "node 'N' (stage) has held frame F for T ms", for printing
};

// What a source does when the pipeline is full (PipelinedExecutor only; one frame at a time
// nothing ever waits).
enum class SourcePolicy {
  block,   // wait for room: recordings, nothing is dropped
  latest,  // keep reading; the newest frame replaces a waiting stale one, which is counted as
           // dropped: live cameras, where an old frame is worth less than a new one
};

struct RunOptions {
  std::int64_t max_frames = -1;  // < 0: until a source ends the stream
  // Called after every frame, in frame order (progress display); may be empty.
  std::function<void(const FrameEvent&)> on_frame;
  // Receives stage warnings already prefixed with node and frame; may be empty (then dropped).
  std::function<void(const std::string&)> on_warning;
  // Keep one CallRecord per stage call in RunStats::calls (for `facet run --trace`).
  bool record_calls = false;
  // Keep which frame each time and metric value belongs to, and each frame's stem
  // (NodeStats::call_frames, metric_frames, RunStats::frame_indices, frame_stems), for per-frame
  // reports. Off, a long live run does not grow by them (about 0.5 KB per frame).
  bool record_frames = false;
  // A stage call running longer than this is reported once to on_stall (zero: never). The call
  // is not interrupted: a stage cannot be stopped safely from outside, so what to do (wait, or
  // end the process) is the caller's choice.
  std::chrono::milliseconds stall_after{0};
  std::function<void(const StallReport&)> on_stall;
  // Every source of a graph shares its frames, so they share one policy.
  SourcePolicy source_policy = SourcePolicy::block;
  // Set to true from anywhere (a signal handler among them) to end the run early: no frame starts
  // once it is seen, the frames already begun run to their end (every sink gets them whole), and
  // the stages are closed as at the end of a stream (a recording is finished properly). May be
  // null; must outlive run().
  const std::atomic<bool>* stop = nullptr;

  bool stop_requested() const { return stop != nullptr && stop->load(std::memory_order_relaxed); }
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
