#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "facet/framework/executor.hpp"
#include "facet/framework/run_report.hpp"
#include "facet/framework/statistics.hpp"
#include "session.hpp"

namespace facet::cli {
namespace {

struct RunArgs {
  PluginOptions plugins;
  GraphOptions graph;
  std::int64_t frames = -1;
  bool profile = false;
  bool quiet = false;
  std::filesystem::path json_file;
};

// A one-line progress display on an interactive terminal, refreshed at most 10 times a second.
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  ~ProgressLine() { finish(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(const FrameEvent& event) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    shown_ = true;
    std::cerr << fmt::format("\r\033[Kframe {:>6}  {:<24}  {:7.2f} ms", event.index + 1, event.stem,
                             event.frame_ms)
              << std::flush;
  }
  void finish() {
    if (shown_) std::cerr << "\r\033[K" << std::flush;
    shown_ = false;
  }

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_{};
};

int run(const RunArgs& args) {
  auto loaded = load_and_validate(args.plugins, args.graph);
  if (loaded->exit_code != kOk) return loaded->exit_code;

  RunStats stats;
  try {
    SequentialExecutor executor(loaded->graph);
    ProgressLine progress(!args.quiet && isatty(STDERR_FILENO) == 1);
    RunOptions options;
    options.max_frames = args.frames;
    options.on_frame = [&](const FrameEvent& event) { progress.update(event); };
    options.on_warning = [&](const std::string& message) {
      progress.finish();
      std::cerr << message << '\n';
    };
    stats = executor.run(options);
  } catch (const RunError& e) {
    std::cerr << "\nerror: " << e.what() << '\n';
    return kRuntimeFailure;
  }

  if (!args.quiet) {
    std::cerr << fmt::format("{}: {} frame(s), {:.2f} ms per frame (median)\n", loaded->graph.name,
                             stats.frames, median(stats.frame_ms));
  }
  if (args.profile) write_profile_table(std::cout, stats);
  if (!args.json_file.empty()) {
    std::ofstream out(args.json_file);
    write_run_json(out, stats, loaded->graph.name, loaded->spec.variant);
    if (!out) {
      std::cerr << "error: cannot write " << args.json_file.string() << '\n';
      return kRuntimeFailure;
    }
  }
  return kOk;
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* command = app.add_subcommand("run", "Run a graph over its input");
  add_graph_options(*command, args->graph);
  add_plugin_options(*command, args->plugins);
  command->add_option("--frames,-n", args->frames, "Stop after N frames")
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--profile", args->profile,
                    "Print per-stage median and p95 time (ms) after the run");
  command->add_option("--json", args->json_file,
                      "Write run statistics (frames, per-stage and total median/p95 ms) as JSON");
  command->add_flag("--quiet,-q", args->quiet, "No progress line and no summary");
  command->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace facet::cli
