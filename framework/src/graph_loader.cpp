// Loading a graph file: parse, check the structure, resolve graph params, apply the selected
// variant and --set overrides, substitute ${...} and split `node.port` references.

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <sstream>
#include <system_error>

#include "facet/framework/graph_spec.hpp"
#include "graph_compose.hpp"
#include "graph_document.hpp"
#include "graph_substitution.hpp"
#include "graph_variants.hpp"
#include "yaml_checks.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using detail::absolute_dir_of;
using detail::kGraphDirParam;
using detail::ParamSubstitution;
using detail::RawGraph;
using detail::RawNode;

SourceLocation command_line() {
  return {kCommandLineFile, 0, 0};
}

// Graph params: the file's defaults, then --param. Their values may use built-ins only, so that
// the order in which params are declared never matters.
std::map<std::string, std::string> resolve_graph_params(const RawGraph& raw,
                                                        const fs::path& graph_dir,
                                                        const LoadOptions& options,
                                                        Diagnostics& diagnostics) {
  const ParamSubstitution builtins({{kGraphDirParam, graph_dir.generic_string()}});
  std::map<std::string, std::string> params;
  std::vector<std::string> declared;
  for (const auto& param : raw.params) {
    declared.push_back(param.name);
    if (param.name == kGraphDirParam) {
      diagnostics.error(param.where,
                        "graph parameter 'graph_dir' is built in and cannot be "
                        "redefined");
      continue;
    }
    params[param.name] = builtins.expand(param.text, param.where, diagnostics).value_or("");
  }
  for (const auto& [name, value] : options.params) {
    const std::string option = "--param " + name + "=" + value + ": ";
    if (params.count(name) == 0) {
      diagnostics.error(command_line(),
                        option + "unknown graph parameter '" + name + "'" +
                            detail::suggestion_suffix(name, declared, "the graph declares"));
      if (declared.empty()) {
        diagnostics.note(command_line(), "the graph declares no parameters");
      }
      continue;
    }
    if (auto expanded = builtins.expand(value, command_line(), diagnostics)) {
      params[name] = *expanded;
    }
  }
  return params;
}

std::vector<fs::path> resolve_plugin_paths(const RawGraph& raw, const fs::path& graph_dir,
                                           const ParamSubstitution& substitution,
                                           Diagnostics& diagnostics) {
  std::vector<fs::path> paths;
  for (const auto& path : raw.plugin_paths) {
    if (auto text = substitution.expand(path.text, path.where, diagnostics)) {
      const fs::path given(*text);
      paths.push_back((given.is_absolute() ? given : graph_dir / given).lexically_normal());
    }
  }
  return paths;
}

void select_variant(RawGraph& raw, const std::string& variant, const std::string& file,
                    Diagnostics& diagnostics) {
  if (variant.empty()) return;
  if (raw.find_variant(variant) != nullptr) {
    detail::apply_variant(raw, variant);
    return;
  }
  const auto names = raw.variant_names();
  diagnostics.error(command_line(), "--variant " + variant + ": unknown variant '" + variant + "'" +
                                        detail::suggestion_suffix(variant, names, ""));
  if (names.empty()) {
    diagnostics.note({file, 0, 0}, "the graph defines no variants");
  } else {
    diagnostics.note({file, 0, 0}, "the graph defines: " + detail::join(names, ", "));
  }
}

// `--replace node=stage`: the node gets the stage, with its inputs and the stage's defaults (the
// old params belong to the old stage); `--set` then gives the params.
void apply_command_line_replaces(RawGraph& raw, const LoadOptions& options,
                                 Diagnostics& diagnostics) {
  for (const auto& [id, stage] : options.replaces) {
    const std::string option = "--replace " + id + "=" + stage + ": ";
    if (!detail::is_identifier(id) || stage.empty()) {
      diagnostics.error(command_line(), option + "expected 'node=stage'");
      continue;
    }
    RawNode* node = raw.find_node(id);
    if (node == nullptr) {
      diagnostics.error(command_line(), option + "unknown node '" + id + "'" +
                                            detail::suggestion_suffix(id, raw.node_ids(), ""));
      continue;
    }
    detail::RawReplace replace;
    replace.node = id;
    replace.where = command_line();
    replace.stage = detail::RawText{stage, command_line()};
    detail::apply_replace(*node, replace, "");
  }
}

void apply_command_line_sets(RawGraph& raw, const LoadOptions& options, Diagnostics& diagnostics) {
  for (const auto& [key, value] : options.sets) {
    const std::string option = "--set " + key + "=" + value + ": ";
    const auto target = detail::split_node_param(key);
    if (!target) {
      diagnostics.error(command_line(), option + "expected 'node.param=value'");
      continue;
    }
    RawNode* node = raw.find_node(target->first);
    if (node == nullptr) {
      diagnostics.error(command_line(),
                        option + "unknown node '" + target->first + "'" +
                            detail::suggestion_suffix(target->first, raw.node_ids(), ""));
      continue;
    }
    detail::set_param(*node, {target->second, value, command_line(), true, value});
  }
}

// `median.depth` → {median, depth}; the node id and the port must both be identifiers.
std::optional<std::pair<std::string, std::string>> split_reference(const std::string& text) {
  const std::size_t dot = text.find('.');
  if (dot == std::string::npos) return std::nullopt;
  std::string node = text.substr(0, dot);
  std::string port = text.substr(dot + 1);
  if (!detail::is_identifier(node) || !detail::is_identifier(port)) return std::nullopt;
  return std::make_pair(std::move(node), std::move(port));
}

// The final node, with ${...} substituted. What fails here is reported and left empty, so that
// validation can still run and skip it instead of reporting the same problem again.
NodeSpec resolve_node(const RawNode& raw, const ParamSubstitution& substitution,
                      Diagnostics& diagnostics) {
  NodeSpec node;
  node.id = raw.id;
  node.where = raw.where;
  node.inputs_where = raw.inputs_where;
  node.replaced_stage = raw.replaced_stage;
  node.replaced_by_variant = raw.replaced_by_variant;
  if (raw.stage) {
    node.stage_where = raw.stage->where;
    node.stage = substitution.expand(raw.stage->text, raw.stage->where, diagnostics).value_or("");
  }
  for (const auto& input : raw.inputs) {
    InputBinding binding{input.port, {}, {}, input.ref.where};
    if (auto text = substitution.expand(input.ref.text, input.ref.where, diagnostics)) {
      if (auto reference = split_reference(*text)) {
        binding.from_node = reference->first;
        binding.from_port = reference->second;
      } else {
        diagnostics.error(input.ref.where, "malformed reference '" + *text + "' for input '" +
                                               input.port + "' of node '" + raw.id +
                                               "': expected 'node.port'");
      }
    }
    node.inputs.push_back(std::move(binding));
  }
  for (const auto& param : raw.params) {
    auto text = substitution.expand(param.text, param.where, diagnostics);
    node.params.push_back(
        {param.name, text.value_or(param.text), param.where, text.has_value(), param.text});
  }
  return node;
}

// `when: PARAM` keeps a node only while the graph parameter PARAM is set (not empty), so that a
// graph can write files, say, only when given an output folder. True when the node stays.
bool node_is_wanted(const RawNode& node, const std::map<std::string, std::string>& params,
                    std::vector<LeftOutNode>& left_out, Diagnostics& diagnostics) {
  if (!node.when) return true;
  const auto& [name, where] = *node.when;
  const auto param = params.find(name);
  if (param == params.end()) {
    std::vector<std::string> declared;
    for (const auto& [declared_name, value] : params)
      declared.push_back(declared_name);
    diagnostics.error(where, "'when' of node '" + node.id + "' names no graph parameter: '" + name +
                                 "'" +
                                 detail::suggestion_suffix(name, declared, "the graph declares"));
    return true;  // validated like any node, so that its other problems are reported too
  }
  if (!param->second.empty()) return true;
  left_out.push_back(
      {node.id, "graph parameter '" + name + "' is empty", where,
       "node '" + node.id + "' exists only when '" + name + "' is set (--param " + name + "=...)"});
  return false;
}

// `inputs:` / `outputs:` entries, with ${...} substituted and the reference split.
std::vector<GraphPort> resolve_graph_ports(const std::vector<detail::RawInput>& raw,
                                           const std::string& what,
                                           const ParamSubstitution& substitution,
                                           Diagnostics& diagnostics) {
  std::vector<GraphPort> ports;
  for (const auto& entry : raw) {
    const auto text = substitution.expand(entry.ref.text, entry.ref.where, diagnostics);
    if (!text) continue;
    const auto reference = split_reference(*text);
    if (!reference) {
      diagnostics.error(entry.ref.where, "malformed reference '" + *text + "' for graph " + what +
                                             " '" + entry.port + "': expected 'node.port'");
      continue;
    }
    ports.push_back({entry.port, reference->first, reference->second, entry.ref.where});
  }
  return ports;
}

// `headline:` must name a node of the graph. Its metric is checked only by a run: stages do not
// declare the metrics they report. A node that `when:` leaves out is fine (the run then reports
// no headline, and says so); one that a composition removed is an error, since the derived graph
// then needs a headline of its own.
std::optional<HeadlineSpec> check_headline(const RawGraph& raw, Diagnostics& diagnostics) {
  if (!raw.headline) return std::nullopt;
  const HeadlineSpec& headline = *raw.headline;
  const auto named = [&headline](const auto& node) { return node.id == headline.node; };
  if (std::any_of(raw.nodes.begin(), raw.nodes.end(), named)) return headline;
  const auto removed = std::find_if(raw.removed.begin(), raw.removed.end(), named);
  if (removed != raw.removed.end()) {
    // Inherited from the base: the graph that removed the node names another headline.
    const bool inherited = headline.where.file != removed->where.file;
    diagnostics.error(headline.where,
                      "node " + detail::in_quotes(headline.node) +
                          " in 'headline' is left out: " + removed->reason +
                          (inherited ? "; name another in that graph's 'headline:'" : ""));
    diagnostics.note(removed->where, removed->note);
  } else {
    diagnostics.error(headline.where,
                      "unknown node " + detail::in_quotes(headline.node) + " in 'headline'" +
                          detail::suggestion_suffix(headline.node, raw.node_ids(), ""));
  }
  return std::nullopt;
}

// The YAML text of a graph file checked and read into its structure; nothing when it is not a
// graph at all (reported).
std::optional<RawGraph> read_document(const std::string& yaml, const std::string& file,
                                      Diagnostics& diagnostics) {
  YAML::Node root;
  try {
    if (!detail::refuse_aliases(yaml, file, diagnostics)) return std::nullopt;
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& error) {
    const SourceLocation where =
        error.mark.is_null() ? SourceLocation{file, 0, 0}
                             : SourceLocation{file, error.mark.line + 1, error.mark.column + 1};
    diagnostics.error(where, error.msg);
    return std::nullopt;
  }
  if (root.IsNull()) {
    // Only blank lines and comments: empty; anything else is text yaml-cpp read as nothing.
    bool blank = true;
    std::istringstream lines(yaml);
    for (std::string line; blank && std::getline(lines, line);) {
      const std::size_t first = line.find_first_not_of(" \t\r");
      blank = first == std::string::npos || line[first] == '#';
    }
    diagnostics.error({file, 0, 0}, blank ? "the graph file is empty"
                                          : "the graph file holds no YAML value: a graph file is "
                                            "a map (facet, name, params, nodes, ...)");
    return std::nullopt;
  }
  if (!root.IsMap()) {
    diagnostics.error(detail::location_of(root, file),
                      "a graph file must be a map (facet, name, params, nodes, ...), got " +
                          std::string(detail::kind_name(root)));
    return std::nullopt;
  }
  detail::report_duplicate_keys(root, file, diagnostics);
  return detail::parse_graph_document(root, file, diagnostics);
}

// The whole text of a file, or why it cannot be read.
struct FileText {
  std::string text;
  std::string error;
};

FileText read_text_file(const fs::path& file) {
  std::error_code error;
  const auto status = fs::status(file, error);
  if (!fs::exists(status)) return {"", "no such file"};
  if (fs::is_directory(status)) return {"", "it is a directory"};
  std::ifstream in(file, std::ios::binary);
  if (!in) return {"", std::generic_category().message(errno)};
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return {"", "read error"};
  return {text.str(), ""};
}

std::optional<RawGraph> read_base_file(const fs::path& file, const SourceLocation& requested_at,
                                       Diagnostics& diagnostics) {
  const FileText content = read_text_file(file);
  if (!content.error.empty()) {
    diagnostics.error(requested_at,
                      "cannot read base graph '" + file.string() + "': " + content.error);
    return std::nullopt;
  }
  return read_document(content.text, file.string(), diagnostics);
}

}  // namespace

const ParamSetting* NodeSpec::find_param(const std::string& name) const {
  const auto it = std::find_if(params.begin(), params.end(),
                               [&](const ParamSetting& p) { return p.name == name; });
  return it == params.end() ? nullptr : &*it;
}

const NodeSpec* GraphSpec::find_node(const std::string& id) const {
  const auto it =
      std::find_if(nodes.begin(), nodes.end(), [&](const NodeSpec& n) { return n.id == id; });
  return it == nodes.end() ? nullptr : &*it;
}

GraphSpec load_graph_text(const std::string& yaml, const std::filesystem::path& display_name,
                          const LoadOptions& options, Diagnostics& diagnostics) {
  GraphSpec graph;
  graph.file = display_name;
  graph.name = display_name.stem().string();
  graph.graph_dir = absolute_dir_of(display_name);
  graph.variant = options.variant;
  const std::string file = display_name.string();

  std::optional<RawGraph> document = read_document(yaml, file, diagnostics);
  if (!document) return graph;
  RawGraph raw = std::move(*document);
  const auto read_base = [&](const fs::path& base, const SourceLocation& requested_at) {
    return read_base_file(base, requested_at, diagnostics);
  };
  detail::resolve_extends(raw, display_name, read_base, diagnostics);
  graph.left_out = raw.removed;
  if (raw.name) graph.name = *raw.name;
  graph.description = raw.description;
  graph.variants = raw.variant_names();
  graph.params = resolve_graph_params(raw, graph.graph_dir, options, diagnostics);

  auto substitutions = graph.params;
  substitutions[kGraphDirParam] = graph.graph_dir.generic_string();
  const ParamSubstitution substitution(std::move(substitutions));
  graph.plugin_paths = resolve_plugin_paths(raw, graph.graph_dir, substitution, diagnostics);

  detail::check_variants(raw, diagnostics);
  select_variant(raw, options.variant, file, diagnostics);
  apply_command_line_replaces(raw, options, diagnostics);
  apply_command_line_sets(raw, options, diagnostics);
  for (const auto& node : raw.nodes) {
    if (!node_is_wanted(node, graph.params, graph.left_out, diagnostics)) continue;
    graph.nodes.push_back(resolve_node(node, substitution, diagnostics));
  }
  graph.inputs = resolve_graph_ports(raw.graph_inputs, "input", substitution, diagnostics);
  graph.outputs = resolve_graph_ports(raw.graph_outputs, "output", substitution, diagnostics);
  graph.headline = check_headline(raw, diagnostics);
  return graph;
}

GraphSpec load_graph_file(const std::filesystem::path& file, const LoadOptions& options,
                          Diagnostics& diagnostics) {
  const auto cannot_read = [&](const std::string& why) {
    diagnostics.error({file.string(), 0, 0}, "cannot read graph file: " + why);
    GraphSpec graph;
    graph.file = file;
    graph.name = file.stem().string();
    graph.graph_dir = absolute_dir_of(file);
    return graph;
  };
  const FileText content = read_text_file(file);
  if (!content.error.empty()) return cannot_read(content.error);
  return load_graph_text(content.text, file, options, diagnostics);
}

}  // namespace facet
