#pragma once
// Stages for the pipelined executor's tests. They report what they saw to one thread-safe probe
// (stages only see their Params), and detect for themselves what must never happen: a serial
// stage called for two frames at once, or out of order.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "facet/framework/registry.hpp"
#include "facet/stage.hpp"
#include "facet/types/images.hpp"
#include "test_graph.hpp"

namespace facet::test {

struct PipelineProbe {
  std::mutex mutex;
  std::condition_variable changed;
  std::map<std::string, std::vector<std::int64_t>> frames;  // node id → frames, in call order
  std::map<std::string, int> instances;                     // stage name → instances created
  std::map<std::string, int> most_at_once;                  // node id → most concurrent calls
  std::vector<std::string> overlaps;                        // serial calls that overlapped
  std::vector<std::string> events;                          // "open id", "close id"
  std::int64_t source_calls = 0;
  int parallelism = 0;  // what ptest.parallel's context said
  bool helped = false;  // a piece of ptest.parallel ran on another thread

  void reset() {
    const std::lock_guard lock(mutex);
    frames.clear();
    instances.clear();
    most_at_once.clear();
    overlaps.clear();
    events.clear();
    source_calls = 0;
    parallelism = 0;
    helped = false;
  }
};

inline PipelineProbe& pipeline_probe() {
  static PipelineProbe probe;
  return probe;
}

// Counts the calls of one node in progress; reports the most seen at once.
class CallCounter {
 public:
  explicit CallCounter(std::atomic<int>& in_call, const std::string& node) : in_call_(in_call) {
    const int now = ++in_call_;
    auto& probe = pipeline_probe();
    const std::lock_guard lock(probe.mutex);
    probe.most_at_once[node] = std::max(probe.most_at_once[node], now);
  }
  ~CallCounter() { --in_call_; }
  CallCounter(const CallCounter&) = delete;
  CallCounter& operator=(const CallCounter&) = delete;

 private:
  std::atomic<int>& in_call_;
};

inline void record_frame(const ProcessContext& ctx) {
  auto& probe = pipeline_probe();
  const std::lock_guard lock(probe.mutex);
  probe.frames[ctx.node_id()].push_back(ctx.frame_index());
  probe.changed.notify_all();
}

inline void count_instance(const std::string& stage) {
  auto& probe = pipeline_probe();
  const std::lock_guard lock(probe.mutex);
  ++probe.instances[stage];
}

inline void record_event(const std::string& event) {
  auto& probe = pipeline_probe();
  const std::lock_guard lock(probe.mutex);
  probe.events.push_back(event);
}

// Emits `frames` 4x4 depth images holding frame index + 1, then ends the stream.
class CountingSource final : public Stage {
 public:
  static StageSpec spec() {
    return StageSpec("ptest.source", "Emits `frames` small depth images, then ends.")
        .output<DepthImage>("depth", "4x4 pixels holding the frame index + 1.")
        .param("frames", 8, "Frames to emit.", {.min = 0})
        .param("gap_every", 0, "Leave the output empty every n-th frame (0 = never).", {.min = 0})
        .concurrency(Concurrency::serial);
  }
  explicit CountingSource(const Params& p)
      : frames_(p.get_int("frames")), gap_every_(p.get_int("gap_every")) {}
  void open(const OpenContext& ctx) override { record_event("open " + ctx.node_id); }
  void close() override { record_event("close source"); }
  void process(ProcessContext& ctx) override {
    {
      auto& probe = pipeline_probe();
      const std::lock_guard lock(probe.mutex);
      ++probe.source_calls;
      probe.changed.notify_all();
    }
    if (ctx.frame_index() >= frames_) {
      ctx.end_of_stream();
      return;
    }
    record_frame(ctx);
    emit_counting_frame(ctx, gap_every_, frames_);
  }

 private:
  std::int64_t frames_;
  std::int64_t gap_every_;
};

// Passes its input on after `work_us` of busy work; records the frames it saw and flags a call
// that overlaps another of the same instance set. Declared with the concurrency its name says.
template <Concurrency kMode>
class PassStage final : public Stage {
 public:
  static std::string name() { return std::string("ptest.") + std::string(to_string(kMode)); }
  static StageSpec spec() {
    return StageSpec(name(), "Forwards its input; watches how it is called.")
        .template input<DepthImage>("depth", "Anything.")
        .template output<DepthImage>("depth", "The input, unchanged.")
        .param("work_us", 200, "Busy time per call, so that calls get the chance to overlap.",
               {.unit = "us", .min = 0})
        .param("fail_at", -1, "Throw a StageError at this frame (-1 = never).", {.min = -1})
        .concurrency(kMode);
  }
  explicit PassStage(const Params& p)
      : work_us_(p.get_int("work_us")), fail_at_(p.get_int("fail_at")) {
    count_instance(name());
  }
  void open(const OpenContext& ctx) override { record_event("open " + ctx.node_id); }
  void close() override { record_event("close " + name()); }
  void process(ProcessContext& ctx) override {
    const CallCounter counter(in_call_, ctx.node_id());
    if (kMode == Concurrency::serial || kMode == Concurrency::clonable) {
      // One instance never sees two frames at once under these two declarations.
      if (instance_busy_.exchange(true)) {
        const std::lock_guard lock(pipeline_probe().mutex);
        pipeline_probe().overlaps.push_back(ctx.node_id() + " frame " +
                                            std::to_string(ctx.frame_index()));
      }
    }
    if (ctx.frame_index() == fail_at_) {
      instance_busy_ = false;
      throw StageError("deliberate failure");
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(work_us_);
    while (std::chrono::steady_clock::now() < until)
      std::this_thread::yield();
    record_frame(ctx);
    ctx.output_packet("depth", ctx.input_packet("depth"));
    instance_busy_ = false;
  }

 private:
  std::int64_t work_us_;
  std::int64_t fail_at_;
  std::atomic<bool> instance_busy_{false};
  // Calls of all instances of this stage type (one node per type in each test).
  static inline std::atomic<int> in_call_{0};
};

// A sink that declares itself reentrant: the executor still hands it frames in order. With
// `hold_until_calls` > 0 its first call waits until the source has been called that often, so
// that a `latest` source has to read past a full pipeline.
class OrderedSink final : public Stage {
 public:
  static StageSpec spec() {
    return StageSpec("ptest.sink", "Records the frames it receives.")
        .input<DepthImage>("depth", "Anything.")
        .param("hold_until_calls", 0, "Wait in the first call for this many source calls.",
               {.min = 0})
        .param("stall_at", -1, "Block at this frame until a stall has been reported.", {.min = -1})
        .concurrency(Concurrency::reentrant);
  }
  explicit OrderedSink(const Params& p)
      : hold_until_calls_(p.get_int("hold_until_calls")), stall_at_(p.get_int("stall_at")) {}
  void open(const OpenContext& ctx) override { record_event("open " + ctx.node_id); }
  void close() override { record_event("close sink"); }
  void process(ProcessContext& ctx) override {
    const CallCounter counter(in_call_, ctx.node_id());
    auto& probe = pipeline_probe();
    if (hold_until_calls_ > 0 && !held_) {
      held_ = true;
      std::unique_lock lock(probe.mutex);
      probe.changed.wait(lock, [&] { return probe.source_calls >= hold_until_calls_; });
    }
    if (ctx.frame_index() == stall_at_) {
      std::unique_lock lock(probe.mutex);
      // Released by the test's stall handler; the long timeout only keeps a broken watchdog from
      // hanging the suite.
      probe.changed.wait_for(lock, std::chrono::seconds(60), [&] { return stall_released; });
    }
    record_frame(ctx);
  }

  static inline bool stall_released = false;  // guarded by the probe's mutex

 private:
  std::int64_t hold_until_calls_;
  std::int64_t stall_at_;
  bool held_ = false;
  static inline std::atomic<int> in_call_{0};
};

// Splits each call into `items` pieces with ProcessContext::parallel_for and checks that every
// piece ran exactly once. With `wait_for_help`, the first piece waits (up to 10 s) until another
// thread has run a piece, so that a pool that never lends its workers fails the test instead of
// passing by luck. `fail_item` >= 0 throws in that piece.
class ParallelStage final : public Stage {
 public:
  static StageSpec spec() {
    return StageSpec("ptest.parallel", "Splits its work with parallel_for; checks the pieces.")
        .input<DepthImage>("depth", "Anything.")
        .output<DepthImage>("depth", "The input, unchanged.")
        .param("items", 64, "Pieces of work per call.", {.min = 0})
        .param("wait_for_help", false, "The first piece waits for a piece on another thread.")
        .param("fail_item", -1, "Throw a StageError in this piece (-1 = never).", {.min = -1})
        .concurrency(Concurrency::serial);
  }
  explicit ParallelStage(const Params& p)
      : items_(p.get_int("items")),
        wait_for_help_(p.get_bool("wait_for_help")),
        fail_item_(p.get_int("fail_item")) {}
  void process(ProcessContext& ctx) override {
    std::vector<int> runs(static_cast<std::size_t>(items_), 0);
    const auto caller = std::this_thread::get_id();
    std::mutex mutex;
    std::condition_variable helped;
    bool other_thread = false;
    ctx.parallel_for(items_, 1, [&](std::int64_t begin, std::int64_t end) {
      const bool helper = std::this_thread::get_id() != caller;
      {
        const std::lock_guard lock(mutex);
        if (helper) other_thread = true;
        helped.notify_all();
      }
      for (std::int64_t i = begin; i < end; ++i) {
        if (i == fail_item_) throw StageError("deliberate failure in item " + std::to_string(i));
        ++runs[static_cast<std::size_t>(i)];
      }
      if (begin == 0 && wait_for_help_) {
        std::unique_lock lock(mutex);
        helped.wait_for(lock, std::chrono::seconds(10), [&] { return other_thread; });
      }
    });
    {
      const std::lock_guard lock(pipeline_probe().mutex);
      auto& probe = pipeline_probe();
      probe.parallelism = ctx.parallelism();
      probe.helped = probe.helped || other_thread;
      for (std::size_t i = 0; i < runs.size(); ++i) {
        if (runs[i] != 1) {
          probe.overlaps.push_back("item " + std::to_string(i) + " ran " + std::to_string(runs[i]) +
                                   " times");
        }
      }
    }
    record_frame(ctx);
    ctx.output_packet("depth", ctx.input_packet("depth"));
  }

 private:
  std::int64_t items_;
  bool wait_for_help_;
  std::int64_t fail_item_;
};

inline void add_pipeline_test_stages(Registry& registry) {
  registry.add<ParallelStage>();
  registry.add<CountingSource>();
  registry.add<PassStage<Concurrency::serial>>();
  registry.add<PassStage<Concurrency::clonable>>();
  registry.add<PassStage<Concurrency::reentrant>>();
  registry.add<OrderedSink>();
}

}  // namespace facet::test
