#pragma once
// The pipelined executor: several frames in flight on a fixed pool of threads, so that a machine
// with more cores processes more frames per second, while writing exactly what the sequential
// executor writes.
//
// Each stage runs as its StageSpec's Concurrency allows:
// - serial: one instance, frames strictly in order, one at a time (sources, sinks, trackers);
// - clonable: one instance per thread, each used by one frame at a time;
// - reentrant: one shared instance, called for several frames at once.
// A sink (a stage without outputs) always sees its frames in order, whatever it declares: files
// written in frame order are what a user expects to find if the run is interrupted.
//
// At most `in_flight` frames are in the pipeline; a source waits for room (SourcePolicy::block)
// or keeps reading, the newest frame replacing one that waits (SourcePolicy::latest). Among the
// ready stage calls, the oldest frame's come first, so a frame leaves the pipeline as early as
// it can.

#include <memory>

#include "facet/framework/executor.hpp"

namespace facet {

struct PipelinedExecutorOptions {
  int threads = 0;    // 0: one per hardware thread
  int in_flight = 0;  // frames in the pipeline at once; 0: twice the threads
};

class PipelinedExecutor {
 public:
  // Instantiates every stage (clonable stages once per thread); throws RunError naming the node
  // when a constructor fails. `graph` (and the Registry behind it) must outlive the executor.
  PipelinedExecutor(const ValidatedGraph& graph, PipelinedExecutorOptions options);
  ~PipelinedExecutor();
  PipelinedExecutor(const PipelinedExecutor&) = delete;
  PipelinedExecutor& operator=(const PipelinedExecutor&) = delete;

  // As SequentialExecutor::run: the same statistics, warnings and errors. The first failure
  // stops the run: calls in progress finish, no new one starts, every stage is closed, and the
  // failure is thrown as a RunError.
  RunStats run(const RunOptions& options = {});

  int threads() const;
  int in_flight() const;
  // How many instances of node `index` exist (1 unless the stage is clonable).
  std::size_t instances(std::size_t index) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facet
