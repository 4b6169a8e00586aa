#include "facet/framework/pipelined_executor.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "node_runtime.hpp"
#include "stall_watchdog.hpp"

namespace facet {
namespace {

using detail::Clock;

struct PipelineNode {
  const ValidatedNode* spec = nullptr;
  Concurrency mode = Concurrency::serial;
  bool source = false;
  std::vector<std::size_t> producers;  // distinct nodes feeding this one
  std::vector<detail::StageInstance> instances;
  std::vector<std::size_t> free_instances;  // clonable: instances not in a call
  bool busy = false;                        // serial: a call in progress
};

enum class State : unsigned char { waiting, running, done };

// One frame in the pipeline: the state of every node for it, and every node's context (inputs,
// outputs, metrics, warnings), which live until the frame leaves the pipeline.
struct Slot {
  bool used = false;
  bool admitted = false;   // past its sources: a `latest` frame waits unadmitted for room
  bool cancelled = false;  // past the end of the stream: nothing new starts; freed when idle
  bool ending = false;     // cancelled, the frame in which a source ended the stream: its calls
                           // so far are still counted when it is retired
  bool started = false;    // its first source call has begun (`start` is set)
  std::int64_t frame = -1;
  Clock::time_point start;
  std::vector<State> state;
  std::vector<double> call_ms;  // < 0: the node did not run (an empty required input)
  std::vector<ProcessContext> contexts;
  std::size_t done = 0;
  std::size_t running = 0;
  std::size_t sources_left = 0;
};

struct Task {
  std::size_t slot;
  std::size_t node;
  std::size_t instance;
  std::string stem;
};

constexpr std::int64_t kNoEnd = std::numeric_limits<std::int64_t>::max();

// One parallel_for() of a stage call, whose chunks the pool's idle workers help with.
struct ParallelJob {
  const std::function<void(std::size_t)>* chunk = nullptr;
  std::size_t chunks = 0;
  std::size_t next = 0;     // the first chunk nobody has taken yet
  std::size_t running = 0;  // chunks taken and not yet returned
  std::exception_ptr error;
};

}  // namespace

struct PipelinedExecutor::Impl {
  Impl(const ValidatedGraph& graph, PipelinedExecutorOptions options);

  // The pool as stages borrow it (ProcessContext::parallel_for): chunks run on the calling
  // thread and on workers that find no stage call to make.
  class Lending final : public ParallelRunner {
   public:
    explicit Lending(Impl& impl) : impl_(impl) {}
    int concurrency() const override { return impl_.threads_; }
    void run(std::size_t chunks, const std::function<void(std::size_t)>& chunk) override {
      impl_.run_parallel(chunks, chunk);
    }

   private:
    Impl& impl_;
  };

  RunStats run(const RunOptions& options);

  // --- everything below runs with mutex_ held, except execute() ---
  bool can_start_frame() const;
  bool finished() const { return failed_ || (used_slots_ == 0 && !can_start_frame()); }
  void start_frame(std::size_t slot, bool admitted);
  void refill();
  std::optional<Task> pick();
  std::optional<Task> find_task();
  void complete(const Task& task, double call_ms, Clock::time_point call_start, int thread);
  void end_stream_at(std::int64_t frame);
  void free_slot(Slot& slot);
  void retire();
  void drop_stale_frames(const Slot& newest);
  const FrameInfo* frame_of(const Slot& slot) const;
  std::string stem_of(const Slot& slot) const;
  void fail(std::exception_ptr error);

  void work(int thread);
  void execute(const Task& task, int thread);
  // Borrowed parallelism: run_parallel() is called without mutex_, run_chunk() with it held
  // (it releases it while the chunk runs).
  void run_parallel(std::size_t chunks, const std::function<void(std::size_t)>& chunk);
  bool help_with_a_chunk(std::unique_lock<std::mutex>& lock);
  void run_chunk(ParallelJob& job, std::unique_lock<std::mutex>& lock);
  void close_all(std::string& first_error);

  const ValidatedGraph& graph_;
  int threads_;
  int in_flight_;
  std::vector<PipelineNode> nodes_;

  // Run state, guarded by mutex_.
  std::mutex mutex_;
  std::condition_variable wake_;
  const RunOptions* options_ = nullptr;
  detail::StallWatchdog* watchdog_ = nullptr;
  Clock::time_point run_start_;
  std::vector<Slot> slots_;
  std::size_t used_slots_ = 0;
  int admitted_ = 0;
  std::int64_t next_frame_ = 0;
  std::int64_t end_frame_ = kNoEnd;  // the frame in which a source ended the stream
  bool latest_ = false;
  bool failed_ = false;
  std::exception_ptr error_;
  std::vector<char> blocked_;       // find_task(): serial nodes an older frame still needs
  bool skipped_ = false;            // find_task() marked a node done without a call
  std::vector<ParallelJob*> jobs_;  // parallel_for() calls with chunks nobody has taken
  Lending lending_{*this};
  RunStats stats_;
};

PipelinedExecutor::Impl::Impl(const ValidatedGraph& graph, PipelinedExecutorOptions options)
    : graph_(graph),
      threads_(options.threads > 0
                   ? options.threads
                   : std::max(1, static_cast<int>(std::thread::hardware_concurrency()))),
      in_flight_(options.in_flight > 0 ? options.in_flight : 2 * threads_) {
  nodes_.reserve(graph.nodes.size());
  for (const auto& spec : graph.nodes) {
    PipelineNode node;
    node.spec = &spec;
    node.source = spec.stage->spec.is_source();
    // A sink sees its frames in order whatever it declares (see the header).
    node.mode =
        spec.stage->spec.outputs().empty() ? Concurrency::serial : spec.stage->spec.concurrency();
    for (const auto& input : spec.inputs) {
      if (input && std::find(node.producers.begin(), node.producers.end(), input->from_node) ==
                       node.producers.end()) {
        node.producers.push_back(input->from_node);
      }
    }
    // More clones than threads (or than frames in flight) could never all be busy at once.
    const std::size_t count = node.mode == Concurrency::clonable
                                  ? static_cast<std::size_t>(std::min(threads_, in_flight_))
                                  : 1;
    for (std::size_t i = 0; i < count; ++i) {
      node.instances.push_back(detail::create_stage(spec));
      node.free_instances.push_back(count - 1 - i);
    }
    nodes_.push_back(std::move(node));
  }
}

bool PipelinedExecutor::Impl::can_start_frame() const {
  return !failed_ && next_frame_ < end_frame_ &&
         (options_->max_frames < 0 || next_frame_ < options_->max_frames) &&
         !options_->stop_requested();
}

void PipelinedExecutor::Impl::start_frame(std::size_t index, bool admitted) {
  Slot& slot = slots_[index];
  slot.used = true;
  slot.admitted = admitted;
  slot.cancelled = false;
  slot.ending = false;
  slot.started = false;
  slot.frame = next_frame_++;
  std::fill(slot.state.begin(), slot.state.end(), State::waiting);
  std::fill(slot.call_ms.begin(), slot.call_ms.end(), -1.0);
  for (auto& ctx : slot.contexts)
    ctx.begin_frame(slot.frame);
  slot.done = 0;
  slot.running = 0;
  slot.sources_left = static_cast<std::size_t>(
      std::count_if(nodes_.begin(), nodes_.end(), [](const auto& n) { return n.source; }));
  ++used_slots_;
  if (admitted) ++admitted_;
}

void PipelinedExecutor::Impl::free_slot(Slot& slot) {
  slot.used = false;
  if (slot.admitted) --admitted_;
  slot.admitted = false;
  --used_slots_;
  // Let go of the frame's packets now rather than when the slot is reused.
  for (auto& ctx : slot.contexts) {
    ctx.begin_frame(slot.frame);
    for (auto& input : ctx.inputs())
      input = Packet();
  }
}

// Admits waiting frames (oldest first) while there is room, then starts new frames: admitted
// ones while there is room, and for a `latest` source one frame read ahead of the room.
void PipelinedExecutor::Impl::refill() {
  while (admitted_ < in_flight_) {
    Slot* oldest = nullptr;
    for (auto& slot : slots_) {
      if (slot.used && !slot.admitted && !slot.cancelled &&
          (oldest == nullptr || slot.frame < oldest->frame)) {
        oldest = &slot;
      }
    }
    if (oldest == nullptr) break;
    oldest->admitted = true;
    ++admitted_;
  }
  while (can_start_frame()) {
    const auto free =
        std::find_if(slots_.begin(), slots_.end(), [](const Slot& s) { return !s.used; });
    if (free == slots_.end()) return;
    const auto index = static_cast<std::size_t>(free - slots_.begin());
    if (admitted_ < in_flight_) {
      start_frame(index, true);
      continue;
    }
    if (!latest_) return;
    const bool reading_ahead = std::any_of(slots_.begin(), slots_.end(), [](const Slot& s) {
      return s.used && !s.admitted && s.sources_left > 0;
    });
    if (!reading_ahead) start_frame(index, false);
    return;
  }
}

const FrameInfo* PipelinedExecutor::Impl::frame_of(const Slot& slot) const {
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (!nodes_[n].source || slot.state[n] != State::done) continue;
    const FrameInfo* info = detail::frame_of(slot.contexts[n].outputs());
    if (info != nullptr && !info->stem.empty()) return info;
  }
  return nullptr;
}

std::string PipelinedExecutor::Impl::stem_of(const Slot& slot) const {
  const FrameInfo* info = frame_of(slot);
  return info == nullptr ? std::string() : info->stem;
}

// The next stage call to make, if any. Marking nodes done without a call may complete a frame,
// which makes room for another.
std::optional<Task> PipelinedExecutor::Impl::pick() {
  while (true) {
    skipped_ = false;
    auto task = find_task();
    if (!skipped_) return task;
    retire();
    refill();
    if (task) return task;
  }
}

// The oldest frame's calls first, in topological order within a frame. Nodes whose required
// input is empty are marked done on the way (they do not run).
std::optional<Task> PipelinedExecutor::Impl::find_task() {
  std::vector<std::size_t> order;
  order.reserve(slots_.size());
  for (std::size_t s = 0; s < slots_.size(); ++s) {
    if (slots_[s].used && !slots_[s].cancelled) order.push_back(s);
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return slots_[a].frame < slots_[b].frame; });
  std::fill(blocked_.begin(), blocked_.end(), 0);
  for (const std::size_t s : order) {
    Slot& slot = slots_[s];
    for (std::size_t n = 0; n < nodes_.size(); ++n) {
      PipelineNode& node = nodes_[n];
      const bool serial = node.mode == Concurrency::serial;
      if (slot.state[n] != State::waiting) {
        if (serial && slot.state[n] == State::running) blocked_[n] = 1;
        continue;
      }
      if (serial && blocked_[n] != 0) continue;  // an older frame is still to come through it
      const bool ready = (slot.admitted || node.source) &&
                         std::all_of(node.producers.begin(), node.producers.end(),
                                     [&](std::size_t p) { return slot.state[p] == State::done; });
      if (!ready) {
        if (serial) blocked_[n] = 1;
        continue;
      }
      const auto outputs_of = [&](std::size_t i) {
        return std::span<const Packet>(slot.contexts[i].outputs());
      };
      if (!detail::gather_inputs(*node.spec, slot.contexts[n], outputs_of)) {
        slot.state[n] = State::done;  // call_ms stays < 0: skipped
        ++slot.done;
        skipped_ = true;
        continue;
      }
      if (serial) blocked_[n] = 1;
      if (serial && node.busy) continue;
      if (node.mode == Concurrency::clonable && node.free_instances.empty()) continue;

      Task task{s, n, 0, stem_of(slot)};
      if (node.mode == Concurrency::clonable) {
        task.instance = node.free_instances.back();
        node.free_instances.pop_back();
      }
      if (serial) node.busy = true;
      slot.state[n] = State::running;
      ++slot.running;
      if (!slot.started) {
        slot.started = true;
        slot.start = Clock::now();
      }
      return task;
    }
  }
  return std::nullopt;
}

// Frames from `frame` on never reach the sinks: those in the pipeline are cancelled.
void PipelinedExecutor::Impl::end_stream_at(std::int64_t frame) {
  end_frame_ = std::min(end_frame_, frame);
  for (auto& slot : slots_) {
    if (!slot.used || slot.frame < end_frame_) continue;
    slot.cancelled = true;
    slot.ending = slot.frame == end_frame_;
    if (slot.running == 0 && !slot.ending) free_slot(slot);
  }
}

// A `latest` source has read a newer frame: every complete frame still waiting for room is stale.
void PipelinedExecutor::Impl::drop_stale_frames(const Slot& newest) {
  for (auto& slot : slots_) {
    if (&slot == &newest || !slot.used || slot.admitted || slot.cancelled ||
        slot.sources_left > 0 || slot.frame > newest.frame) {
      continue;
    }
    free_slot(slot);
    ++stats_.dropped;
  }
}

// Frames leave the pipeline in order: the oldest one, once every node is done with it. The
// frame that ended the stream leaves last; the calls made for it count as the sequential
// executor counts them (the source's last call, and those before it in that frame).
void PipelinedExecutor::Impl::retire() {
  while (true) {
    Slot* oldest = nullptr;
    for (auto& slot : slots_) {
      if (slot.used && (!slot.cancelled || slot.ending) &&
          (oldest == nullptr || slot.frame < oldest->frame)) {
        oldest = &slot;
      }
    }
    if (oldest == nullptr) return;
    if (oldest->ending) {
      if (oldest->running > 0) return;
      for (std::size_t n = 0; n < nodes_.size(); ++n) {
        if (oldest->state[n] == State::done && oldest->call_ms[n] >= 0.0) {
          detail::account_call(stats_.nodes[n], oldest->contexts[n], oldest->call_ms[n], *options_);
        }
      }
      free_slot(*oldest);
      return;
    }
    if (oldest->done < nodes_.size()) return;
    for (std::size_t n = 0; n < nodes_.size(); ++n) {
      if (oldest->call_ms[n] < 0.0) {
        ++stats_.nodes[n].skipped;
      } else {
        detail::account_call(stats_.nodes[n], oldest->contexts[n], oldest->call_ms[n], *options_);
      }
    }
    const double frame_ms = detail::ms_between(oldest->start, Clock::now());
    stats_.frame_ms.push_back(frame_ms);
    const FrameInfo* info = frame_of(*oldest);
    if (options_->record_frames) {
      stats_.frame_indices.push_back(oldest->frame);
      stats_.frame_stems.push_back(info == nullptr ? std::string() : info->stem);
    }
    ++stats_.frames;
    if (options_->on_frame) {
      options_->on_frame(FrameEvent{oldest->frame, info == nullptr ? std::string() : info->stem,
                                    frame_ms, info == nullptr ? 0 : info->stream_frames});
    }
    free_slot(*oldest);
  }
}

void PipelinedExecutor::Impl::complete(const Task& task, double call_ms,
                                       Clock::time_point call_start, int thread) {
  Slot& slot = slots_[task.slot];
  PipelineNode& node = nodes_[task.node];
  if (node.mode == Concurrency::clonable) node.free_instances.push_back(task.instance);
  node.busy = false;
  slot.state[task.node] = State::done;
  slot.call_ms[task.node] = call_ms;
  ++slot.done;
  --slot.running;
  if (options_->record_calls) {
    stats_.calls.push_back(
        {task.node, slot.frame, thread, detail::ms_between(run_start_, call_start), call_ms});
  }
  if (node.source && !slot.cancelled) {
    --slot.sources_left;
    if (slot.contexts[task.node].at_end_of_stream()) {
      end_stream_at(slot.frame);
    } else if (slot.sources_left == 0 && !slot.admitted) {
      drop_stale_frames(slot);
    }
  }
  if (slot.used && slot.cancelled && !slot.ending && slot.running == 0) free_slot(slot);
  retire();
  refill();
}

void PipelinedExecutor::Impl::fail(std::exception_ptr error) {
  if (!failed_) error_ = std::move(error);
  failed_ = true;
}

void PipelinedExecutor::Impl::execute(const Task& task, int thread) {
  PipelineNode& node = nodes_[task.node];
  ProcessContext& ctx = slots_[task.slot].contexts[task.node];
  detail::StageInstance& instance = node.instances[task.instance];
  watchdog_->begin(thread, *node.spec, ctx.frame_index(), Clock::now());
  detail::call_stage(*instance.stage, ctx, *node.spec, task.stem);
  watchdog_->end(thread);
}

void PipelinedExecutor::Impl::run_chunk(ParallelJob& job, std::unique_lock<std::mutex>& lock) {
  const std::size_t index = job.next++;
  if (job.next == job.chunks) std::erase(jobs_, &job);
  ++job.running;
  lock.unlock();
  std::exception_ptr error;
  try {
    (*job.chunk)(index);
  } catch (...) {
    error = std::current_exception();
  }
  lock.lock();
  --job.running;
  if (error) {
    if (!job.error) job.error = error;
    if (job.next < job.chunks) {  // the chunks not yet taken are not started
      job.next = job.chunks;
      std::erase(jobs_, &job);
    }
  }
}

bool PipelinedExecutor::Impl::help_with_a_chunk(std::unique_lock<std::mutex>& lock) {
  if (jobs_.empty()) return false;
  ParallelJob& job = *jobs_.front();
  run_chunk(job, lock);
  if (job.running == 0 && job.next == job.chunks) wake_.notify_all();  // its caller may wait
  return true;
}

void PipelinedExecutor::Impl::run_parallel(std::size_t chunks,
                                           const std::function<void(std::size_t)>& chunk) {
  if (chunks == 0) return;
  ParallelJob job;
  job.chunk = &chunk;
  job.chunks = chunks;
  std::unique_lock lock(mutex_);
  jobs_.push_back(&job);
  wake_.notify_all();
  // The caller works through the chunks too, so the call finishes with no worker free.
  while (job.next < job.chunks)
    run_chunk(job, lock);
  wake_.wait(lock, [&job] { return job.running == 0; });
  if (job.error) std::rethrow_exception(job.error);
}

void PipelinedExecutor::Impl::work(int thread) {
  std::unique_lock lock(mutex_);
  while (!finished()) {
    // Chunks first: a stage call waits on them, while a new call can start later.
    if (help_with_a_chunk(lock)) continue;
    std::optional<Task> task;
    try {
      task = pick();
    } catch (...) {  // a stage's input could not be gathered, or out of memory
      fail(std::current_exception());
      break;
    }
    if (!task) {
      wake_.wait(lock);
      continue;
    }
    lock.unlock();
    const auto call_start = Clock::now();
    std::exception_ptr error;
    try {
      execute(*task, thread);
    } catch (...) {
      watchdog_->end(thread);
      error = std::current_exception();
    }
    const double call_ms = detail::ms_between(call_start, Clock::now());
    lock.lock();
    if (error) {
      fail(error);
    } else {
      try {
        complete(*task, call_ms, call_start, thread);
      } catch (...) {  // a progress or warning callback threw
        fail(std::current_exception());
      }
    }
    wake_.notify_all();
  }
  wake_.notify_all();
}

void PipelinedExecutor::Impl::close_all(std::string& first_error) {
  for (auto node = nodes_.rbegin(); node != nodes_.rend(); ++node) {
    for (auto instance = node->instances.rbegin(); instance != node->instances.rend(); ++instance) {
      std::string error = detail::close_stage(*instance, *node->spec);
      if (first_error.empty()) first_error = std::move(error);
    }
  }
}

RunStats PipelinedExecutor::Impl::run(const RunOptions& options) {
  detail::require_an_end(graph_, options);
  options_ = &options;
  run_start_ = Clock::now();
  stats_ = RunStats{};
  stats_.nodes = detail::node_stats_for(graph_);
  latest_ = options.source_policy == SourcePolicy::latest;
  slots_.clear();
  // A `latest` source reads one frame ahead of the room and keeps one waiting.
  slots_.resize(static_cast<std::size_t>(in_flight_ + (latest_ ? 2 : 0)));
  for (auto& slot : slots_) {
    slot.state.resize(nodes_.size());
    slot.call_ms.resize(nodes_.size());
    slot.contexts.reserve(nodes_.size());
    for (const auto& node : nodes_) {
      slot.contexts.emplace_back(node.spec->stage->spec, node.spec->id);
      if (threads_ > 1) slot.contexts.back().set_parallel_runner(&lending_);
    }
  }
  blocked_.assign(nodes_.size(), 0);
  used_slots_ = 0;
  admitted_ = 0;
  next_frame_ = 0;
  end_frame_ = kNoEnd;
  failed_ = false;
  error_ = nullptr;

  std::string close_error;
  try {
    for (auto& node : nodes_) {
      for (auto& instance : node.instances)
        detail::open_stage(instance, *node.spec);
    }
  } catch (...) {
    close_all(close_error);
    throw;
  }

  {
    detail::StallWatchdog watchdog(options.stall_after, options.on_stall, threads_);
    watchdog_ = &watchdog;
    {
      const std::lock_guard lock(mutex_);
      refill();
    }
    {
      std::vector<std::jthread> pool;
      pool.reserve(static_cast<std::size_t>(threads_ - 1));
      for (int thread = 1; thread < threads_; ++thread)
        pool.emplace_back([this, thread] { work(thread); });
      work(0);
    }  // joins the pool
    watchdog_ = nullptr;
  }

  close_all(close_error);
  stats_.wall_ms = detail::ms_between(run_start_, Clock::now());
  stats_.stopped = options.stop_requested() && end_frame_ == kNoEnd &&
                   (options.max_frames < 0 || next_frame_ < options.max_frames);
  options_ = nullptr;
  if (error_) std::rethrow_exception(error_);
  if (!close_error.empty()) throw RunError(close_error);
  return std::move(stats_);
}

PipelinedExecutor::PipelinedExecutor(const ValidatedGraph& graph, PipelinedExecutorOptions options)
    : impl_(std::make_unique<Impl>(graph, options)) {}

PipelinedExecutor::~PipelinedExecutor() = default;

RunStats PipelinedExecutor::run(const RunOptions& options) {
  return impl_->run(options);
}

int PipelinedExecutor::threads() const {
  return impl_->threads_;
}
int PipelinedExecutor::in_flight() const {
  return impl_->in_flight_;
}
std::size_t PipelinedExecutor::instances(std::size_t index) const {
  return impl_->nodes_.at(index).instances.size();
}

}  // namespace facet
