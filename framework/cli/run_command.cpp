#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "facet/framework/executor.hpp"
#include "facet/framework/pipelined_executor.hpp"
#include "facet/framework/progress_text.hpp"
#include "facet/framework/run_report.hpp"
#include "facet/framework/statistics.hpp"
#include "facet/framework/trace_writer.hpp"
#include "option_checks.hpp"
#include "session.hpp"
#include "signal_stop.hpp"
#include "warning_throttle.hpp"

namespace facet::cli {
namespace {

struct RunArgs {
  PluginOptions plugins;
  GraphOptions graph;
  std::int64_t frames = -1;
  bool profile = false;
  bool quiet = false;
  std::filesystem::path json_file;
  std::filesystem::path trace_file;
  int threads = 0;  // 0: one per hardware thread
  int in_flight = 0;
  std::string executor = "auto";
  std::string source_policy = "block";
  std::int64_t stall_ms = 5000;
  bool stall_abort = false;
};

// One frame at a time (the reference) or several in flight: `auto` picks the pipeline when
// there is more than one thread to run it on.
bool use_pipeline(const RunArgs& args, int threads) {
  if (args.executor == "sequential") return false;
  if (args.executor == "pipelined") return true;
  return threads > 1;
}

RunStats run_graph(const RunArgs& args, const ValidatedGraph& graph, const RunOptions& options) {
  const int threads = args.threads > 0
                          ? args.threads
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (!use_pipeline(args, threads)) {
    SequentialExecutor executor(graph);
    return executor.run(options);
  }
  PipelinedExecutor executor(graph, PipelinedExecutorOptions{threads, args.in_flight});
  return executor.run(options);
}

// A one-line progress display on an interactive terminal, refreshed at most 10 times a second:
// frame i of N, percent and time left when N is known (progress_text).
class ProgressLine {
 public:
  ProgressLine(bool enabled, std::int64_t max_frames)
      : enabled_(enabled), max_frames_(max_frames), start_(std::chrono::steady_clock::now()) {}
  ~ProgressLine() { finish(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(const FrameEvent& event) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    shown_ = true;
    const double elapsed_s = std::chrono::duration<double>(now - start_).count();
    std::cerr << "\r\033[K" << progress_text(event, max_frames_, elapsed_s) << std::flush;
  }
  void finish() {
    if (shown_) std::cerr << "\r\033[K" << std::flush;
    shown_ = false;
  }

 private:
  bool enabled_;
  std::int64_t max_frames_;
  std::chrono::steady_clock::time_point start_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_{};
};

// Where a run's results went: the `dir` (or `path`) of every sink (a node without outputs) that
// was called at least once, as "node → folder", in graph order.
std::string written_places(const ValidatedGraph& graph, const RunStats& stats) {
  std::string places;
  for (const ValidatedNode& node : graph.nodes) {
    if (!node.stage->spec.outputs().empty()) continue;
    const auto ran = std::find_if(stats.nodes.begin(), stats.nodes.end(), [&](const NodeStats& n) {
      return n.id == node.id && !n.call_ms.empty();
    });
    if (ran == stats.nodes.end()) continue;
    for (const std::string_view name : {"dir", "path"}) {
      if (!node.params.contains(name)) continue;
      const auto* place = std::get_if<std::string>(&node.params.at(name));
      if (place == nullptr || place->empty()) continue;
      places += (places.empty() ? "" : ", ") + node.id + " -> " + *place;
      break;
    }
  }
  return places;
}

int run(const RunArgs& args) {
  auto loaded = load_and_validate(args.plugins, args.graph);
  if (loaded->exit_code != kOk) return loaded->exit_code;

  RunStats stats;
  const SignalStop signals;
  WarningThrottle warnings;
  try {
    ProgressLine progress(!args.quiet && isatty(STDERR_FILENO) == 1, args.frames);
    RunOptions options;
    options.max_frames = args.frames;
    options.record_calls = !args.trace_file.empty();
    options.record_frames = !args.json_file.empty();
    options.source_policy =
        args.source_policy == "latest" ? SourcePolicy::latest : SourcePolicy::block;
    options.on_frame = [&](const FrameEvent& event) { progress.update(event); };
    options.on_warning = [&](const std::string& message) {
      if (!warnings.admit(message)) return;
      progress.finish();
      std::cerr << message << '\n';
    };
    options.stop = &signals.stop();
    options.stall_after = std::chrono::milliseconds(args.stall_ms);
    // Called from the watchdog's thread while the executor's threads keep running: it only
    // prints, and ends the process when asked to, since a hung stage call cannot be stopped.
    options.on_stall = [stall_abort = args.stall_abort](const StallReport& report) {
      std::cerr << "\nwarning: stall: " << report.message << '\n' << std::flush;
      if (stall_abort) {
        std::cerr << "error: stopping the run (--stall-abort)" << std::endl;
        std::_Exit(kRuntimeFailure);
      }
    };
    stats = run_graph(args, loaded->graph, options);
  } catch (const RunError& e) {
    for (const std::string& line : warnings.summary())
      std::cerr << line << '\n';
    std::cerr << "\nerror: " << e.what() << '\n';
    return kRuntimeFailure;
  }

  for (const std::string& line : warnings.summary())
    std::cerr << line << '\n';
  // A node whose required input stayed empty is skipped without a word from the stage: its
  // outputs (often files) are silently missing, so the run says so.
  for (const NodeStats& node : stats.nodes) {
    if (node.skipped == 0) continue;
    std::cerr << fmt::format(
        "warning: node '{}' ({}) was skipped in {} of {} frame(s): a required input was empty "
        "(the node it reads did not set that output)\n",
        node.id, node.stage, node.skipped, stats.frames);
  }

  if (!args.quiet) {
    std::cerr << fmt::format(
                     "{}: {} frame(s), {:.2f} ms per frame (median latency), {:.1f} frames/s",
                     loaded->graph.name, stats.frames, median(stats.frame_ms),
                     stats.throughput_fps())
              << (stats.dropped > 0 ? fmt::format(", {} dropped", stats.dropped) : "") << '\n';
  }
  if (!args.quiet) {
    const std::string places = written_places(loaded->graph, stats);
    if (!places.empty()) std::cerr << "wrote: " << places << '\n';
  }
  if (stats.stopped) {
    // Always said, even with --quiet: a script must learn that the input was not read to its end.
    std::cerr << fmt::format(
        "stopped by {}: {} frame(s) completed and written whole; the rest of the input was not "
        "read\n",
        signal_name(signals.signal()), stats.frames);
  }
  if (args.profile) write_profile_table(std::cout, stats);
  if (!args.json_file.empty()) {
    std::ofstream out(args.json_file);
    write_run_json(out, stats, loaded->graph.name, loaded->spec.variant);
    // A full disk shows only when the buffer is flushed: close before checking.
    out.close();
    if (!out) {
      std::cerr << "error: cannot write " << args.json_file.string() << '\n';
      return kRuntimeFailure;
    }
  }
  if (!args.trace_file.empty()) {
    std::ofstream out(args.trace_file);
    write_chrome_trace(out, stats, loaded->graph.name);
    // A full disk shows only when the buffer is flushed: close before checking.
    out.close();
    if (!out) {
      std::cerr << "error: cannot write " << args.trace_file.string() << '\n';
      return kRuntimeFailure;
    }
  }
  return stats.stopped ? 128 + signals.signal() : kOk;
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* command = app.add_subcommand("run", "Run a graph over its input");
  add_graph_options(*command, args->graph);
  add_plugin_options(*command, args->plugins);
  command->add_option("--frames,-n", args->frames, "Stop after N frames")
      ->check(non_negative_integer());
  command->add_flag("--view", args->graph.view,
                    "Watch the run in a window (io.view, facet_view plugin): the graph's depth "
                    "input and labels output, as its `inputs:`/`outputs:` name them");
  command->add_flag("--profile", args->profile,
                    "Print per-stage median and p95 time (ms) after the run");
  command->add_option("--json", args->json_file,
                      "Write run statistics (frames, per-stage and total median/p95 ms) as JSON");
  command->add_option("--trace", args->trace_file,
                      "Write a Chrome/Perfetto trace (one slice per stage call, per thread) as "
                      "JSON; open it in chrome://tracing or ui.perfetto.dev");
  command
      ->add_option("--threads,-j", args->threads,
                   "Threads that run stages (default: one per hardware thread); 1 runs one "
                   "frame at a time")
      ->check(non_negative_integer());
  command
      ->add_option("--in-flight", args->in_flight,
                   "Frames in the pipeline at once (default: twice the threads)")
      ->check(non_negative_integer());
  command
      ->add_option("--executor", args->executor,
                   "sequential (one frame at a time, the reference), pipelined, or auto "
                   "(pipelined with more than one thread)")
      ->check(CLI::IsMember({"auto", "sequential", "pipelined"}));
  command
      ->add_option("--source-policy", args->source_policy,
                   "When the pipeline is full: block (wait; recordings, nothing dropped) or latest "
                   "(read on, the newest frame replaces a waiting one; live cameras)")
      ->check(CLI::IsMember({"block", "latest"}));
  command
      ->add_option("--stall-ms", args->stall_ms,
                   "Report a stage call that runs longer than this, naming node and frame "
                   "(0: never)")
      ->check(non_negative_integer())
      ->capture_default_str();
  command->add_flag("--stall-abort", args->stall_abort,
                    "End the run with exit code 1 when a stall is reported");
  command->add_flag("--quiet,-q", args->quiet, "No progress line and no summary");
  command->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace facet::cli
