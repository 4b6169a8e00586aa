#pragma once
// What the graph-taking commands share: the options that select and tune a graph, loading the
// plugins it may need, and turning it into a validated graph with every problem printed.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "facet/framework/graph_spec.hpp"
#include "facet/framework/registry.hpp"
#include "facet/framework/validated_graph.hpp"

namespace facet::cli {

struct PluginOptions {
  std::vector<std::filesystem::path> plugin_paths;
};

struct GraphOptions {
  std::filesystem::path graph_file;
  std::vector<std::string> params;    // name=value
  std::vector<std::string> replaces;  // node=stage
  std::vector<std::string> sets;      // node.param=value
  std::string variant;
  bool view = false;  // `run --view`: add a window showing the graph's depth and labels
};

void add_plugin_options(CLI::App& command, PluginOptions& options);
void add_graph_options(CLI::App& command, GraphOptions& options);

// FACET_PLUGIN_PATH, or empty.
std::string plugin_path_environment();

// Loads the plugins from every search directory (including the graph's own plugin paths).
Registry load_registry(const PluginOptions& plugins,
                       const std::vector<std::filesystem::path>& graph_plugin_paths);

// The outcome of loading + validating a graph; `exit_code` is kOk when `graph` can be run.
struct LoadedGraph {
  Registry registry;
  GraphSpec spec;
  ValidatedGraph graph;
  int exit_code = 0;
};

// Whether validation also constructs every node's stage once (and destroys it): stages parse
// structured parameters (a workspace box, an up vector) in their constructors, so only that
// finds their errors before a run. `validate` does it; `run` constructs the stages anyway.
enum class ConstructStages { no, yes };

// Prints diagnostics to stderr. On failure, exit_code is kInvalidGraph, or kPluginFailure when a
// stage is missing while some plugin failed to load (the likely cause).
std::unique_ptr<LoadedGraph> load_and_validate(const PluginOptions& plugins,
                                               const GraphOptions& graph_options,
                                               ConstructStages construct = ConstructStages::no);

// Validates every variant the base graph's file defines, with the base's plugins and the same
// --param/--set, printing each variant's diagnostics; one entry per variant, in file order.
struct VariantCheck {
  std::string variant;
  int exit_code = 0;
};
std::vector<VariantCheck> validate_variants(const LoadedGraph& base, const PluginOptions& plugins,
                                            const GraphOptions& graph_options,
                                            ConstructStages construct = ConstructStages::no);

}  // namespace facet::cli
