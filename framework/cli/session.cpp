#include "session.hpp"

#include <cstdlib>
#include <iostream>

#include "exit_codes.hpp"
#include "facet/framework/diagnostics.hpp"
#include "facet/framework/plugin_loader.hpp"
#include "view_option.hpp"

namespace facet::cli {
namespace {

// "name=value" → pair; the first '=' splits, so values may contain '='.
std::optional<std::pair<std::string, std::string>> split_assignment(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) return std::nullopt;
  return std::make_pair(text.substr(0, eq), text.substr(eq + 1));
}

}  // namespace

void add_plugin_options(CLI::App& command, PluginOptions& options) {
  // One value per occurrence: `--plugin-path DIR graph.yaml` must leave the graph to its place.
  command
      .add_option("--plugin-path", options.plugin_paths,
                  "Directory searched for plugins before all others (repeatable)")
      ->allow_extra_args(false);
}

void add_graph_options(CLI::App& command, GraphOptions& options) {
  command.add_option("graph", options.graph_file, "Graph file (YAML)")->required();
  command
      .add_option("--param,-p", options.params,
                  "Override a graph parameter: name=value (repeatable)")
      ->allow_extra_args(false);
  command
      .add_option("--replace", options.replaces,
                  "Give a node another stage: node=stage, e.g. source=io.pcd; the node keeps its "
                  "inputs, its params start from the new stage's defaults (repeatable, applied "
                  "after --variant, before --set)")
      ->allow_extra_args(false);
  command
      .add_option("--set,-s", options.sets,
                  "Override a node parameter: node.param=value (repeatable, applied last)")
      ->allow_extra_args(false);
  command.add_option("--variant,-V", options.variant,
                     "Apply the variant NAME defined in the graph");
}

std::string plugin_path_environment() {
  const char* value = std::getenv("FACET_PLUGIN_PATH");  // NOLINT(concurrency-mt-unsafe)
  return value == nullptr ? std::string() : std::string(value);
}

Registry load_registry(const PluginOptions& plugins,
                       const std::vector<std::filesystem::path>& graph_plugin_paths) {
  Registry registry;
  load_plugins(
      plugin_search_dirs(plugins.plugin_paths, plugin_path_environment(), graph_plugin_paths),
      registry);
  return registry;
}

namespace {

// Constructs and destroys every node's stage, reporting a constructor's refusal at the node.
void construct_each_stage(const ValidatedGraph& graph, Diagnostics& diagnostics) {
  for (const ValidatedNode& node : graph.nodes) {
    try {
      const auto stage = node.stage->spec.factory()(node.params);
    } catch (const std::exception& e) {
      diagnostics.error(node.where, "node '" + node.id + "' (" + node.stage->spec.name() +
                                        "): its parameters were refused: " + e.what());
    }
  }
}

// Loads and validates the graph with `registry`, or with the plugins its file names when
// `registry` is null. Prints diagnostics (warnings too) to stderr.
std::unique_ptr<LoadedGraph> load_with(const PluginOptions& plugins,
                                       const GraphOptions& graph_options, const Registry* registry,
                                       ConstructStages construct) {
  auto loaded = std::make_unique<LoadedGraph>();
  Diagnostics diagnostics;
  LoadOptions options;
  options.variant = graph_options.variant;
  const SourceLocation command_line{kCommandLineFile, 0, 0};
  for (const auto& text : graph_options.params) {
    if (const auto kv = split_assignment(text)) {
      options.params[kv->first] = kv->second;
    } else {
      diagnostics.error(command_line, "--param expects name=value, got '" + text + "'");
    }
  }
  for (const auto& text : graph_options.replaces) {
    if (const auto kv = split_assignment(text)) {
      options.replaces.push_back(*kv);
    } else {
      diagnostics.error(command_line, "--replace expects node=stage, got '" + text + "'");
    }
  }
  for (const auto& text : graph_options.sets) {
    if (const auto kv = split_assignment(text)) {
      options.sets.push_back(*kv);
    } else {
      diagnostics.error(command_line, "--set expects node.param=value, got '" + text + "'");
    }
  }
  loaded->spec = load_graph_file(graph_options.graph_file, options, diagnostics);
  if (graph_options.view) add_view_node(loaded->spec, diagnostics);
  // Validation runs even after loading errors (it skips what the loader already reported), so a
  // user sees every problem of the file at once, like a compiler.
  if (registry == nullptr) loaded->registry = load_registry(plugins, loaded->spec.plugin_paths);
  const Registry& stages = registry != nullptr ? *registry : loaded->registry;
  loaded->graph = validate_graph(loaded->spec, stages, diagnostics);
  if (construct == ConstructStages::yes && !diagnostics.has_errors()) {
    construct_each_stage(loaded->graph, diagnostics);
  }
  // A plugin that did not load is an error when the graph needs one of its stages (validation
  // reported that, with the failure as a note); otherwise it must not pass in silence either.
  if (registry == nullptr && !diagnostics.has_errors()) {
    for (const auto& failure : stages.failures()) {
      diagnostics.warning({}, "plugin " + failure.file.string() + " did not load (" +
                                  failure.reason +
                                  "); no node of this graph needs it (`facet doctor` lists "
                                  "every plugin)");
    }
  }
  diagnostics.print(std::cerr);  // warnings too
  if (diagnostics.has_errors()) {
    bool missing_stage = false;
    for (const auto& node : loaded->spec.nodes) {
      if (stages.find(node.stage) == nullptr) missing_stage = true;
    }
    const bool plugin_failed = !stages.failures().empty();
    loaded->exit_code = (missing_stage && plugin_failed) ? kPluginFailure : kInvalidGraph;
    std::cerr << diagnostics.error_count() << " error(s) in " << graph_options.graph_file.string()
              << (graph_options.variant.empty() ? "" : ", variant " + graph_options.variant)
              << "\n";
  }
  return loaded;
}

}  // namespace

std::unique_ptr<LoadedGraph> load_and_validate(const PluginOptions& plugins,
                                               const GraphOptions& graph_options,
                                               ConstructStages construct) {
  return load_with(plugins, graph_options, nullptr, construct);
}

std::vector<VariantCheck> validate_variants(const LoadedGraph& base, const PluginOptions& plugins,
                                            const GraphOptions& graph_options,
                                            ConstructStages construct) {
  std::vector<VariantCheck> checks;
  for (const std::string& variant : base.spec.variants) {
    GraphOptions options = graph_options;
    options.variant = variant;
    checks.push_back({variant, load_with(plugins, options, &base.registry, construct)->exit_code});
  }
  return checks;
}

}  // namespace facet::cli
