#pragma once
// A graph file as written: the YAML structure checked and read into plain structs, before
// variants, command-line overrides and ${...} substitution are applied. Scalars keep their text
// and location; nothing here knows about stages.

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "facet/framework/diagnostics.hpp"
#include "facet/framework/graph_spec.hpp"

namespace facet::detail {

struct RawText {
  std::string text;
  SourceLocation where;
};

// `depth: median.depth` before the reference is substituted and split.
struct RawInput {
  std::string port;
  RawText ref;
};

struct RawNode {
  std::string id;
  SourceLocation where;
  std::optional<RawText> stage;  // absent when missing (already reported)
  std::vector<RawInput> inputs;
  std::optional<SourceLocation> inputs_where;
  std::vector<ParamSetting> params;
  std::optional<RawText> when;  // `when: PARAM`: the node exists only while that param is set
  std::string replaced_stage;
  std::string replaced_by_variant;
};

// One entry of a variant's `replace:`; absent parts keep the node's own.
struct RawReplace {
  std::string node;
  SourceLocation where;
  std::optional<RawText> stage;
  std::optional<std::vector<RawInput>> inputs;
  std::optional<SourceLocation> inputs_where;
  std::optional<std::vector<ParamSetting>> params;
};

// One entry of a variant's `set:`, `node.param: value`.
struct RawSet {
  std::string node;
  SourceLocation key_where;
  ParamSetting setting;
};

struct RawVariant {
  std::string name;
  SourceLocation where;
  std::vector<RawText> extends;
  std::vector<RawReplace> replaces;
  std::vector<RawSet> sets;
};

struct RawGraph {
  // Composition: the base graph file this one extends, and its edits of the base's nodes.
  std::optional<RawText> extends;
  std::vector<RawText> removes;
  std::vector<RawText> removed_variants;  // `remove_variants:`, names of the base's variants
  std::vector<RawReplace> replaces;
  std::vector<RawSet> sets;
  std::vector<LeftOutNode> removed;  // what `remove:` took out, for the validator's errors

  std::optional<std::string> name;
  std::string description;
  std::vector<ParamSetting> params;  // graph params and their defaults, in file order
  std::vector<RawText> plugin_paths;
  std::vector<RawNode> nodes;
  std::vector<RawVariant> variants;
  std::vector<RawInput> graph_inputs;   // `inputs:` name: node.port
  std::vector<RawInput> graph_outputs;  // `outputs:` name: node.port
  bool has_graph_inputs = false;        // the file has an `inputs:` key (perhaps empty)
  bool has_graph_outputs = false;
  std::optional<HeadlineSpec> headline;  // `headline:`, its form checked; its node not yet

  RawNode* find_node(const std::string& id);
  const RawVariant* find_variant(const std::string& name) const;
  std::vector<std::string> node_ids() const;
  std::vector<std::string> variant_names() const;
};

// Reads the top-level map of a graph file, reporting every structural problem: unknown keys,
// wrong kinds, a missing or unsupported `facet:` version, invalid node ids.
RawGraph parse_graph_document(const YAML::Node& root, const std::string& file,
                              Diagnostics& diagnostics);

// Splits "node.param" (variant `set:` keys and --set options). Nothing when malformed.
std::optional<std::pair<std::string, std::string>> split_node_param(const std::string& text);

}  // namespace facet::detail
