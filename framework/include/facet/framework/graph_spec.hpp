#pragma once
// A graph file after parsing, variant selection and parameter substitution, but before it is
// checked against the stages that plugins provide. Every element remembers where it came from,
// so later checks can still point at the right line of the right file.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "facet/framework/diagnostics.hpp"
#include "facet/framework/score_goal.hpp"

namespace facet {

// One node parameter as written (after ${...} substitution); typed later against the ParamSpec.
struct ParamSetting {
  std::string name;
  std::string text;      // scalar text, e.g. "5", "0.85", "out/tabletop"
  SourceLocation where;  // of the value (of the --set option for command-line overrides)
  // False when the loader could not resolve the value (an undefined ${...}) and has said so:
  // validation then counts the parameter as set but does not check it again.
  bool resolved = true;
  // As written, before substitution: "${edge_threshold}". What a sweep of a graph parameter
  // looks for to know which node parameters it moves.
  std::string written;
};

// `in: {depth: median.depth}` — input port `port` is fed by `from_node`'s output `from_port`.
struct InputBinding {
  std::string port;
  std::string from_node;
  std::string from_port;
  SourceLocation where;  // of the value "median.depth"
};

struct NodeSpec {
  std::string id;
  std::string stage;
  SourceLocation where;        // of the node's key
  SourceLocation stage_where;  // of the stage name
  std::vector<InputBinding> inputs;
  std::vector<ParamSetting> params;
  // Of the `in:` key when the node has one, even an empty one: a source must not have it.
  std::optional<SourceLocation> inputs_where;
  // Set when a variant's `replace:` swapped the stage, so that port errors can say why the
  // ports differ from the file's: the stage written in the file and the variant that replaced it.
  std::string replaced_stage;
  std::string replaced_by_variant;

  const ParamSetting* find_param(const std::string& name) const;
};

// `inputs: {depth: source.depth}` and `outputs: {labels: objects.objects}`: a named port of the
// graph as a whole, the output `node.port` that a host program feeds (an input: that node is then
// not run) or reads (an output). See facet/pipeline.hpp.
struct GraphPort {
  std::string name;
  std::string node;
  std::string port;
  SourceLocation where;  // of the value "source.depth"
};

// A node written in a graph file but not in this graph: its `when:` graph parameter is empty,
// or a graph extending the file removed it.
struct LeftOutNode {
  std::string id;
  std::string reason;    // "graph parameter 'output' is empty"
  SourceLocation where;  // of the `when:` value or the `remove:` entry
  std::string note;      // said there: how to have the node back
};

// `headline: score.f` or `headline: {metric: score.f, better: higher}`: the metric that reports of
// the graph lead with (facet compare's "best" variant), and which way it is better.
struct HeadlineSpec {
  std::string node;                      // id of the node that reports it
  std::string metric;                    // the metric's name, as the node's stage reports it
  ScoreGoal better = ScoreGoal::higher;  // higher or lower, never none
  SourceLocation where;                  // of the value "score.f"

  std::string key() const { return node + "." + metric; }
};

struct GraphSpec {
  std::filesystem::path file;                 // as given; "<string>" for graphs parsed from memory
  std::string name;                           // `name:`, or the file's stem when absent
  std::string description;                    // `description:`, optional one-liner
  std::filesystem::path graph_dir;            // absolute directory of the file: ${graph_dir}
  std::string variant;                        // the variant applied, empty for none
  std::vector<std::string> variants;          // every variant the file defines
  std::map<std::string, std::string> params;  // graph params after --param overrides
  std::vector<std::filesystem::path> plugin_paths;  // `plugins.paths`, made absolute
  std::vector<NodeSpec> nodes;                      // in file order
  std::vector<LeftOutNode> left_out;                // `when:` or `remove:` took them out
  std::vector<GraphPort> inputs;                    // `inputs:`, in file order
  std::vector<GraphPort> outputs;                   // `outputs:`, in file order
  std::optional<HeadlineSpec> headline;             // `headline:`, when the graph names one

  const NodeSpec* find_node(const std::string& id) const;
};

struct LoadOptions {
  std::map<std::string, std::string> params;                  // --param name=value
  std::vector<std::pair<std::string, std::string>> replaces;  // --replace node=stage, in order
  std::vector<std::pair<std::string, std::string>> sets;      // --set node.param=value, in order
  std::string variant;                                        // --variant NAME
};

// Parses and resolves a graph file. Reports every problem it can find into `diagnostics`;
// the result is only meaningful when diagnostics.has_errors() is false. It may still be passed to
// validate_graph, which skips what the loader rejected, so that one run reports every problem.
GraphSpec load_graph_file(const std::filesystem::path& file, const LoadOptions& options,
                          Diagnostics& diagnostics);

// The same for YAML text held in memory; `display_name` is used in diagnostics and as the base
// for relative paths (its parent directory).
GraphSpec load_graph_text(const std::string& yaml, const std::filesystem::path& display_name,
                          const LoadOptions& options, Diagnostics& diagnostics);

}  // namespace facet
