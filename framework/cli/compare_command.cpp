// facet compare: variants of one graph merged into one run, timed fairly, reported side by side.

#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "compare_html.hpp"
#include "compare_sweep.hpp"
#include "exit_codes.hpp"
#include "facet/framework/compare_report.hpp"
#include "facet/framework/compare_summary.hpp"
#include "facet/framework/executor.hpp"
#include "facet/framework/graph_merge.hpp"
#include "facet/version.hpp"
#include "option_checks.hpp"
#include "report_context.hpp"
#include "report_headline.hpp"
#include "report_images.hpp"
#include "session.hpp"
#include "warning_throttle.hpp"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

// The name that stands for the graph as written, without any variant.
constexpr const char* kBaseVariant = "base";
// The graph parameter that, by the convention of the bundled graphs, roots every sink's output.
constexpr const char* kOutputParam = "output";

struct CompareArgs {
  PluginOptions plugins;
  fs::path graph_file;
  std::string variants;
  std::vector<std::string> sweeps;  // node.param=start:stop:step
  std::string variant;              // the variant a sweep starts from
  double plateau_within = 0.01;
  std::vector<std::string> params;
  std::vector<std::string> replaces;
  std::vector<std::string> sets;
  std::int64_t frames = -1;
  std::int64_t warmup = 2;
  fs::path out_dir;
  int images = 3;
  std::string images_pick = "disagree";
  int image_width = 320;
  std::string command_line;
  bool quiet = false;
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const auto first = item.find_first_not_of(' ');
    const auto last = item.find_last_not_of(' ');
    if (first != std::string::npos) items.push_back(item.substr(first, last - first + 1));
  }
  return items;
}

bool parse_assignments(const std::vector<std::string>& texts, const char* option,
                       std::vector<std::pair<std::string, std::string>>& out) {
  for (const auto& text : texts) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::cerr << "error: " << option << " expects name=value, got '" << text << "'\n";
      return false;
    }
    out.emplace_back(text.substr(0, eq), text.substr(eq + 1));
  }
  return true;
}

bool is_sink(const Registry& registry, const NodeSpec& node) {
  const StageEntry* entry = registry.find(node.stage);
  return entry != nullptr && entry->spec.outputs().empty() && !entry->spec.inputs().empty();
}

bool is_under(const fs::path& path, const fs::path& dir) {
  const std::string p = path.lexically_normal().generic_string();
  const std::string d = dir.lexically_normal().generic_string();
  return p.size() >= d.size() && p.compare(0, d.size(), d) == 0 &&
         (p.size() == d.size() || p[d.size()] == '/');
}

// A sink whose `dir` is not below the variant's folder (the graph does not root it in
// ${output}) writes to <variant folder>/<node id> instead, so that variants never share files.
void keep_outputs_apart(GraphSpec& spec, const Registry& registry, const fs::path& variant_dir) {
  for (auto& node : spec.nodes) {
    if (!is_sink(registry, node)) continue;
    for (auto& param : node.params) {
      if (param.name == "dir" && !is_under(param.text, variant_dir)) {
        param.text = (variant_dir / node.id).generic_string();
      }
    }
  }
}

bool write_file(const fs::path& file, const std::function<void(std::ostream&)>& write) {
  std::ofstream out(file, std::ios::binary);
  write(out);
  if (!out) {
    std::cerr << "error: cannot write " << file.string() << '\n';
    return false;
  }
  return true;
}

// The input depth and ground truth of each shown frame, beside the variants' images, when the
// graph reads a dataset folder: its `input` parameter, and the `labels_dir` of its `source` node
// (the folder of the ground truth the eval stage scores against).
void add_input_and_truth(std::vector<ImageRow>& rows, const GraphSpec& graph, int max_width) {
  const auto input = graph.params.find("input");
  if (input == graph.params.end()) return;
  std::string truth_folder;
  if (const NodeSpec* source = graph.find_node("source")) {
    if (const ParamSetting* labels = source->find_param("labels_dir")) truth_folder = labels->text;
  }
  const fs::path dataset(input->second);
  std::error_code error;
  for (auto& row : rows) {
    const fs::path depth = dataset / "depth" / (row.stem + ".png");
    if (fs::is_regular_file(depth, error)) row.input_uri = depth_data_uri(depth, max_width);
    if (truth_folder.empty()) continue;
    const fs::path truth = dataset / truth_folder / (row.stem + ".png");
    if (fs::is_regular_file(truth, error)) row.truth_uri = png_data_uri(truth, max_width);
  }
}

// A headline the graph names but no variant reported is a mistake in the graph (a misspelt
// metric) or a run that did not score; the report says so too, instead of naming a best variant.
void warn_if_headline_is_missing(const CompareSummary& summary) {
  if (!summary.headline || !summary.headline->from_graph || summary.headline->reported) return;
  Diagnostics diagnostics;
  diagnostics.warning(summary.headline->where, "headline " + summary.headline->key() +
                                                   ": no variant reported it; " +
                                                   why_headline_is_missing(summary));
  diagnostics.print(std::cerr);
}

int compare(const CompareArgs& args) {
  LoadOptions base_options;
  std::vector<std::pair<std::string, std::string>> params;
  if (!parse_assignments(args.params, "--param", params) ||
      !parse_assignments(args.replaces, "--replace", base_options.replaces) ||
      !parse_assignments(args.sets, "--set", base_options.sets)) {
    return kUsage;
  }
  for (const auto& [name, value] : params)
    base_options.params[name] = value;

  // The graph as written: its variants, its params and where its plugins are.
  Diagnostics diagnostics;
  const GraphSpec base = load_graph_file(args.graph_file, base_options, diagnostics);
  if (diagnostics.has_errors()) {
    diagnostics.print(std::cerr);
    return kInvalidGraph;
  }
  const Registry registry = load_registry(args.plugins, base.plugin_paths);

  // What to compare: named variants, or the points of a sweep (each one the graph with
  // --variant, --set and the point's values applied, in that order).
  struct Request {
    std::string name;
    std::string file_variant;  // applied from the graph file; empty for none
    std::vector<std::pair<std::string, std::string>> sets;    // node.param -> value
    std::vector<std::pair<std::string, std::string>> params;  // graph parameter -> value
  };
  std::vector<Request> requests;
  PreparedSweep sweep;
  if (!args.sweeps.empty()) {
    if (!args.variants.empty()) {
      std::cerr << "error: --sweep compares the points of one sweep; give --variant V to sweep "
                   "on top of variant V instead of --variants\n";
      return kUsage;
    }
    sweep = prepare_sweep(args.sweeps, args.graph_file, base_options, args.variant, registry);
    if (sweep.exit_code != kOk) return sweep.exit_code;
    for (const auto& point : sweep.points)
      requests.push_back({point.name, args.variant, point.sets, point.params});
  } else if (!args.variant.empty()) {
    std::cerr << "error: --variant " << args.variant
              << " selects where a --sweep starts; to compare variants, list them with "
                 "--variants\n";
    return kUsage;
  }
  std::vector<std::string> names =
      args.variants.empty() ? base.variants : split_list(args.variants);
  if (!requests.empty()) {
    names.clear();
    for (const auto& request : requests)
      names.push_back(request.name);
  } else {
    for (const auto& name : names) {
      const bool is_base =
          name == kBaseVariant &&
          std::find(base.variants.begin(), base.variants.end(), name) == base.variants.end();
      requests.push_back({name, is_base ? "" : name, {}, {}});
    }
  }
  if (names.empty()) {
    std::cerr << "error: " << args.graph_file.string()
              << " defines no variants; name what to compare with --variants (e.g. "
                 "--variants base,other after adding a variant 'other')\n";
    return kUsage;
  }
  const fs::path out_dir =
      args.out_dir.empty() ? fs::path("out/compare") / base.name : args.out_dir;

  std::vector<VariantGraph> variants;
  std::vector<std::string> variant_changes;  // against the graph as written, same output folder
  for (const auto& request : requests) {
    const std::string& name = request.name;
    LoadOptions written_options = base_options;
    const fs::path variant_dir = out_dir / name;
    if (base.params.count(kOutputParam) > 0) {
      written_options.params[kOutputParam] = variant_dir.generic_string();
    }
    LoadOptions options = written_options;
    options.variant = request.file_variant;
    options.sets.insert(options.sets.end(), request.sets.begin(), request.sets.end());
    for (const auto& [param, value] : request.params)
      options.params[param] = value;
    GraphSpec spec = load_graph_file(args.graph_file, options, diagnostics);
    Diagnostics written_diagnostics;  // the same file, its problems are reported above
    variant_changes.push_back(describe_changes(
        load_graph_file(args.graph_file, written_options, written_diagnostics), spec));
    keep_outputs_apart(spec, registry, variant_dir);
    variants.push_back({name, std::move(spec)});
  }
  if (diagnostics.has_errors()) {
    diagnostics.print(std::cerr);
    if (std::find(base.variants.begin(), base.variants.end(), kBaseVariant) == base.variants.end())
      std::cerr << "note: '" << kBaseVariant << "' names the graph without any variant\n";
    return kInvalidGraph;
  }

  MergedGraph merged;
  try {
    MergeOptions merge_options;
    merge_options.keep_per_variant = [&](const NodeSpec& node) { return is_sink(registry, node); };
    merged = merge_variants(variants, merge_options);
  } catch (const std::invalid_argument& error) {
    std::cerr << "error: --variants: " << error.what() << '\n';
    return kUsage;
  }
  const ValidatedGraph graph = validate_graph(merged.spec, registry, diagnostics);
  diagnostics.print(std::cerr);
  if (diagnostics.has_errors()) {
    const bool plugin_failed = !registry.failures().empty();
    return plugin_failed ? kPluginFailure : kInvalidGraph;
  }

  // One frame at a time: no variant's stage competes with another's for a core, and every
  // stage call of a frame sees the same caches and clock state as its neighbours.
  RunStats stats;
  WarningThrottle warnings;
  try {
    RunOptions options;
    options.max_frames = args.frames;
    options.record_calls = true;
    options.record_frames = true;
    options.on_warning = [&warnings](const std::string& message) {
      if (warnings.admit(message)) std::cerr << message << '\n';
    };
    SequentialExecutor executor(graph);
    stats = executor.run(options);
  } catch (const RunError& error) {
    for (const std::string& line : warnings.summary())
      std::cerr << line << '\n';
    std::cerr << "error: " << error.what() << '\n';
    return kRuntimeFailure;
  }
  for (const std::string& line : warnings.summary())
    std::cerr << line << '\n';
  if (stats.frames <= args.warmup) {
    std::cerr << fmt::format(
        "warning: {} frame(s) run, all of them warm-up (--warmup {}): no time is reported\n",
        stats.frames, args.warmup);
  }

  CompareSummary summary = summarize_comparison(merged, graph, stats, args.warmup);
  if (!sweep.points.empty()) {
    summary.sweep =
        summarize_sweep(summary, sweep.axes, sweep.points, args.variant, args.plateau_within);
  }
  write_compare_table(std::cout, summary);
  warn_if_headline_is_missing(summary);

  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) {
    std::cerr << "error: cannot create " << out_dir.string() << ": " << error.message() << '\n';
    return kRuntimeFailure;
  }
  std::vector<std::pair<std::string, fs::path>> variant_dirs;
  for (const auto& name : names)
    variant_dirs.emplace_back(name, out_dir / name);
  ReportContext context;
  context.facet_version = FACET_SDK_VERSION_STRING;
  context.command_line = args.command_line;
  context.date_utc = utc_now_text();
  if (const auto input = base.params.find("input"); input != base.params.end()) {
    // Relative to where the command ran, as a person would have typed it: worked out on the
    // text, so that a folder reached through a symbolic link is named by the link.
    std::error_code ignored;
    context.input = fs::path(input->second)
                        .lexically_normal()
                        .lexically_proximate(fs::current_path(ignored))
                        .generic_string();
  }
  context.variant_changes = variant_changes;
  const bool scored = summary.headline && summary.headline->reported;
  context.images_where_they_disagree =
      args.images_pick == "disagree" && scored && summary.variants.size() > 1;
  const auto stems = frames_to_show(summary, static_cast<std::size_t>(args.images),
                                    context.images_where_they_disagree);
  auto images = collect_variant_images(variant_dirs, stems, args.image_width);
  add_input_and_truth(images, base, args.image_width);
  std::vector<SweepPlotFile> plots;
  if (summary.sweep) {
    auto written_plots = write_sweep_plots(out_dir, *summary.sweep);
    if (!written_plots) return kRuntimeFailure;
    plots = std::move(*written_plots);
  }
  const bool written = write_file(out_dir / "compare.json",
                                  [&](std::ostream& out) { write_compare_json(out, summary); }) &&
                       write_file(out_dir / "compare.csv",
                                  [&](std::ostream& out) { write_compare_csv(out, summary); }) &&
                       write_file(out_dir / "report.html", [&](std::ostream& out) {
                         write_compare_html(out, summary, images, context, plots);
                       });
  if (!written) return kRuntimeFailure;
  if (!args.quiet) {
    std::string plot_names;
    for (const auto& plot : plots)
      plot_names += fmt::format(", {}", plot.name);
    std::cerr << fmt::format(
        "\nwrote {0}/compare.json, compare.csv{1} and report.html; each "
        "variant's own outputs are in {0}/<variant>/\n",
        out_dir.generic_string(), plot_names);
  }
  return kOk;
}

}  // namespace

void add_compare_command(CLI::App& app, int& exit_code, std::string command_line) {
  auto args = std::make_shared<CompareArgs>();
  args->command_line = std::move(command_line);
  CLI::App* command = app.add_subcommand(
      "compare",
      "Run variants of a graph side by side (shared nodes once) and report time, metrics and "
      "images");
  command->add_option("graph", args->graph_file, "Graph file (YAML) that defines the variants")
      ->required();
  command->add_option("--variants", args->variants,
                      "Variants to compare, comma-separated ('base' = the graph without a "
                      "variant); default: every variant of the file");
  command->add_option("--sweep", args->sweeps,
                      "Compare the points of a parameter sweep instead of variants: "
                      "node.param=start:stop:step, or param=start:stop:step for a graph "
                      "parameter, which moves every node parameter written with its ${param} "
                      "(values start + i*step up to stop; repeatable: a grid over every "
                      "combination, at most 200 points). Each point is a variant named "
                      "node.param=value; OUT/sweep_<node.param>.svg plots every score against "
                      "each parameter. A bad sweep (range, step, unknown or non-numeric "
                      "parameter, value out of range) exits 2. Examples: --sweep "
                      "edges.threshold=0.80:0.90:0.01, --sweep edge_threshold=0.80:0.90:0.01");
  command->add_option("--variant", args->variant,
                      "With --sweep: the graph file's variant the sweep starts from (default: "
                      "the graph as written)");
  command
      ->add_option("--plateau-within", args->plateau_within,
                   "With --sweep: the plateau of the headline score (the graph's 'headline:', "
                   "F by default) is the widest range of a parameter over which it stays within "
                   "this much of its best")
      ->check(non_negative_number())
      ->capture_default_str();
  command->add_option("--frames,-n", args->frames, "Stop after N frames")
      ->check(non_negative_integer());
  command->add_option("--warmup", args->warmup, "Leading frames left out of the timing")
      ->check(non_negative_integer())
      ->capture_default_str();
  command->add_option("--out,-o", args->out_dir,
                      "Folder for compare.json, compare.csv, report.html and one sub-folder of "
                      "outputs per variant (default: out/compare/<graph name>)");
  command->add_option("--images", args->images, "Frames whose images go into the report")
      ->check(non_negative_integer())
      ->capture_default_str();
  command
      ->add_option("--images-pick", args->images_pick,
                   "Which frames: disagree (where the variants' headline metric, F by "
                   "default, differs most, when they report it) or first")
      ->check(CLI::IsMember({"disagree", "first"}))
      ->capture_default_str();
  command
      ->add_option("--image-width", args->image_width,
                   "Width the report's images are shrunk to at most (pixels)")
      ->check(positive_integer())
      ->capture_default_str();
  command->add_option("--param,-p", args->params,
                      "Override a graph parameter for every variant: name=value (repeatable; "
                      "'output' is set per variant)");
  command->add_option("--replace", args->replaces,
                      "Give a node another stage in every variant: node=stage (repeatable, "
                      "applied after the variant, before --set)");
  command->add_option("--set,-s", args->sets,
                      "Override a node parameter for every variant: node.param=value "
                      "(repeatable, applied after the variant)");
  add_plugin_options(*command, args->plugins);
  command->add_flag("--quiet,-q", args->quiet, "Only the table");
  command->callback([args, &exit_code] { exit_code = compare(*args); });
}

}  // namespace facet::cli
