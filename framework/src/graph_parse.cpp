#include <algorithm>

#include "facet/framework/score_goal.hpp"
#include "graph_document.hpp"
#include "yaml_checks.hpp"

namespace facet::detail {
namespace {

constexpr const char* kFormatVersion = "1";

const std::vector<std::string> kTopLevelKeys = {
    "facet",   "name",    "description", "extends",  "remove",
    "replace", "set",     "params",      "plugins",  "nodes",
    "inputs",  "outputs", "variants",    "headline", "remove_variants"};
const std::vector<std::string> kNodeKeys = {"stage", "in", "params", "when"};
const std::vector<std::string> kReplaceKeys = {"stage", "in", "params"};
const std::vector<std::string> kVariantKeys = {"extends", "replace", "set"};
const std::vector<std::string> kPluginsKeys = {"paths"};
const std::vector<std::string> kHeadlineKeys = {"metric", "better"};
const std::vector<std::string> kGoalNames = {"higher", "lower"};

// Reads one document; holds the file name and the diagnostics so that each step stays short.
class DocumentReader {
 public:
  DocumentReader(std::string file, Diagnostics& diagnostics)
      : file_(std::move(file)), diagnostics_(diagnostics) {}

  RawGraph read(const YAML::Node& root) {
    RawGraph graph;
    bool has_version = false;
    bool has_nodes = false;
    std::optional<SourceLocation> extends_where;
    std::vector<MapEntry> edits;  // top-level remove/replace/set, which need a base
    for (const auto& entry : map_entries(root, file_, diagnostics_)) {
      if (entry.key == "facet") {
        has_version = true;
        check_version(entry);
      } else if (entry.key == "name") {
        if (auto text = scalar(entry, "'name'")) graph.name = text->text;
      } else if (entry.key == "description") {
        if (auto text = scalar(entry, "'description'")) graph.description = text->text;
      } else if (entry.key == "params") {
        graph.params = settings(entry, "'params'", /*check_names=*/true);
      } else if (entry.key == "plugins") {
        graph.plugin_paths = plugin_paths(entry);
      } else if (entry.key == "nodes") {
        has_nodes = true;
        graph.nodes = nodes(entry);
      } else if (entry.key == "inputs") {
        graph.has_graph_inputs = true;
        graph.graph_inputs = graph_ports(entry, "'inputs'");
      } else if (entry.key == "outputs") {
        graph.has_graph_outputs = true;
        graph.graph_outputs = graph_ports(entry, "'outputs'");
      } else if (entry.key == "extends") {
        graph.extends = scalar(entry, "'extends' (the base graph's file)");
        extends_where = entry.key_where;
      } else if (entry.key == "remove") {
        graph.removes = names(entry, "'remove' (node ids of the base graph)");
        edits.push_back(entry);
      } else if (entry.key == "remove_variants") {
        graph.removed_variants =
            names(entry, "'remove_variants' (variant names of the base graph)");
        edits.push_back(entry);
      } else if (entry.key == "replace") {
        graph.replaces = replaces(entry, "'replace'");
        edits.push_back(entry);
      } else if (entry.key == "set") {
        graph.sets = sets(entry, "'set'");
        edits.push_back(entry);
      } else if (entry.key == "variants") {
        graph.variants = variants(entry);
      } else if (entry.key == "headline") {
        graph.headline = headline(entry);
      } else {
        report_unknown_key(entry, "the graph", kTopLevelKeys, diagnostics_);
      }
    }
    const SourceLocation top = location_of(root, file_);
    if (!has_version) {
      diagnostics_.error(top, "missing key 'facet' (the format version: 'facet: 1')");
    }
    // A graph that extends another may add no node of its own.
    if (!has_nodes && !extends_where) diagnostics_.error(top, "missing key 'nodes'");
    if (!extends_where) {
      for (const auto& edit : edits) {
        diagnostics_.error(edit.key_where, "'" + edit.key +
                                               "' edits the nodes of a base graph, but this graph "
                                               "has no 'extends: BASE.yaml'");
      }
    }
    return graph;
  }

 private:
  SourceLocation value_where(const MapEntry& entry) const {
    // An empty value ("stage:") has no useful mark of its own: point at its key.
    if (entry.value.IsNull()) return entry.key_where;
    return location_of(entry.value, file_);
  }

  std::optional<RawText> scalar(const MapEntry& entry, const std::string& what) {
    const SourceLocation where = value_where(entry);
    if (!expect_scalar(entry.value, where, what, diagnostics_)) return std::nullopt;
    return RawText{entry.value.Scalar(), where};
  }

  void check_version(const MapEntry& entry) {
    const auto version = scalar(entry, "'facet' (the format version)");
    if (version && version->text != kFormatVersion) {
      diagnostics_.error(version->where, "unsupported graph format version '" + version->text +
                                             "'; this facet reads 'facet: " + kFormatVersion + "'");
    }
  }

  bool map_value(const MapEntry& entry, const std::string& what) {
    return expect_map(entry.value, value_where(entry), what, diagnostics_);
  }

  // A map of name: scalar (graph params, node params).
  std::vector<ParamSetting> settings(const MapEntry& entry, const std::string& what,
                                     bool check_names) {
    std::vector<ParamSetting> out;
    if (!map_value(entry, what)) return out;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      if (check_names && !is_identifier(item.key)) {
        diagnostics_.error(item.key_where, "invalid parameter name " + in_quotes(item.key) +
                                               ": use letters, digits and '_'");
        continue;
      }
      if (auto text = scalar(item, "parameter " + in_quotes(item.key))) {
        out.push_back({item.key, text->text, text->where, true, text->text});
      }
    }
    return out;
  }

  std::vector<RawText> plugin_paths(const MapEntry& entry) {
    std::vector<RawText> out;
    if (!map_value(entry, "'plugins'")) return out;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      if (item.key != "paths") {
        report_unknown_key(item, "'plugins'", kPluginsKeys, diagnostics_);
        continue;
      }
      if (!expect_sequence(item.value, value_where(item), "'plugins.paths'", diagnostics_)) {
        continue;
      }
      for (const auto& path : item.value) {
        const SourceLocation where = location_of(path, file_);
        if (expect_scalar(path, where, "a plugin path", diagnostics_)) {
          out.push_back({path.Scalar(), where});
        }
      }
    }
    return out;
  }

  std::vector<RawInput> inputs(const MapEntry& entry, const std::string& what) {
    std::vector<RawInput> out;
    if (!map_value(entry, what)) return out;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      if (auto ref = scalar(item, "input " + in_quotes(item.key))) out.push_back({item.key, *ref});
    }
    return out;
  }

  // `inputs:` / `outputs:` of the graph: name: node.port, the names being identifiers (a host
  // program uses them as keys, Python as dictionary keys).
  std::vector<RawInput> graph_ports(const MapEntry& entry, const std::string& what) {
    std::vector<RawInput> out;
    for (auto& port : inputs(entry, what)) {
      if (!is_identifier(port.port)) {
        diagnostics_.error(port.ref.where, "invalid name " + in_quotes(port.port) + " in " + what +
                                               ": use letters, digits and '_'");
        continue;
      }
      out.push_back(std::move(port));
    }
    return out;
  }

  // `headline: node.metric`, or `headline: {metric: node.metric, better: higher}`. Which way is
  // better may be left out for the metrics whose way goal_of_metric knows (F, times, ...).
  std::optional<HeadlineSpec> headline(const MapEntry& entry) {
    std::optional<RawText> metric;
    std::optional<RawText> better;
    if (entry.value.IsMap()) {
      bool has_metric = false;
      for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
        if (item.key == "metric") {
          has_metric = true;
          metric = scalar(item, "'metric' of 'headline'");
        } else if (item.key == "better") {
          better = scalar(item, "'better' of 'headline'");
        } else {
          report_unknown_key(item, "'headline'", kHeadlineKeys, diagnostics_);
        }
      }
      if (!has_metric) {
        diagnostics_.error(entry.key_where,
                           "'headline' has no 'metric' (the node and its metric, e.g. score.f)");
      }
    } else if (entry.value.IsScalar()) {
      metric = RawText{entry.value.Scalar(), value_where(entry)};
    } else {
      diagnostics_.error(value_where(entry),
                         "'headline' must be 'node.metric' or a map {metric: node.metric, better: "
                         "higher or lower}, got " +
                             std::string(kind_name(entry.value)));
    }
    if (!metric) return std::nullopt;
    const auto target = split_node_param(metric->text);
    if (!target) {
      diagnostics_.error(metric->where, "malformed headline " + in_quotes(metric->text) +
                                            ": expected 'node.metric', e.g. 'score.f'");
      return std::nullopt;
    }
    HeadlineSpec spec{target->first, target->second, goal_of_metric(target->second), metric->where};
    if (better) {
      if (better->text == "higher") {
        spec.better = ScoreGoal::higher;
      } else if (better->text == "lower") {
        spec.better = ScoreGoal::lower;
      } else {
        diagnostics_.error(better->where,
                           "'better' of 'headline' must be 'higher' or 'lower', got " +
                               in_quotes(better->text) +
                               suggestion_suffix(better->text, kGoalNames, ""));
        return std::nullopt;
      }
    } else if (spec.better == ScoreGoal::none) {
      diagnostics_.error(metric->where,
                         "headline " + in_quotes(metric->text) +
                             ": the metric describes the scene or the run, neither way is better "
                             "by default; say which with 'headline: {metric: " +
                             metric->text + ", better: higher}' (or lower)");
      return std::nullopt;
    }
    return spec;
  }

  std::vector<RawNode> nodes(const MapEntry& entry) {
    std::vector<RawNode> out;
    if (!map_value(entry, "'nodes'")) return out;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      if (!is_identifier(item.key)) {
        diagnostics_.error(item.key_where,
                           "invalid node id " + in_quotes(item.key) +
                               ": use letters, digits and '_', not starting with a digit");
        continue;
      }
      out.push_back(node(item));
    }
    if (out.empty() && entry.value.IsMap()) {
      diagnostics_.error(entry.key_where, "the graph has no nodes");
    }
    return out;
  }

  RawNode node(const MapEntry& entry) {
    RawNode node;
    node.id = entry.key;
    node.where = entry.key_where;
    const std::string what = "node " + in_quotes(node.id);
    if (!map_value(entry, what)) return node;
    bool has_stage = false;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      if (item.key == "stage") {
        has_stage = true;
        node.stage = scalar(item, "'stage' of " + what);
      } else if (item.key == "in") {
        node.inputs_where = item.key_where;
        node.inputs = inputs(item, "'in' of " + what);
      } else if (item.key == "params") {
        node.params = settings(item, "'params' of " + what, /*check_names=*/false);
      } else if (item.key == "when") {
        node.when = scalar(item, "'when' of " + what + " (the name of a graph parameter)");
      } else {
        report_unknown_key(item, what, kNodeKeys, diagnostics_);
      }
    }
    if (!has_stage) diagnostics_.error(node.where, what + " has no 'stage'");
    return node;
  }

  std::vector<RawVariant> variants(const MapEntry& entry) {
    std::vector<RawVariant> out;
    if (!map_value(entry, "'variants'")) return out;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      out.push_back(variant(item));
    }
    return out;
  }

  RawVariant variant(const MapEntry& entry) {
    RawVariant variant;
    variant.name = entry.key;
    variant.where = entry.key_where;
    const std::string what = "variant " + in_quotes(variant.name);
    if (!map_value(entry, what)) return variant;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      if (item.key == "extends") {
        variant.extends =
            names(item, "'extends' of " + what + " (a variant name or a list of them)");
      } else if (item.key == "replace") {
        variant.replaces = replaces(item, "'replace' of " + what);
      } else if (item.key == "set") {
        variant.sets = sets(item, "'set' of " + what);
      } else {
        report_unknown_key(item, what, kVariantKeys, diagnostics_);
      }
    }
    return variant;
  }

  // A list of names, or one name.
  std::vector<RawText> names(const MapEntry& entry, const std::string& what) {
    std::vector<RawText> out;
    if (entry.value.IsSequence()) {
      for (const auto& name : entry.value) {
        const SourceLocation where = location_of(name, file_);
        if (expect_scalar(name, where, "a name in " + what, diagnostics_)) {
          out.push_back({name.Scalar(), where});
        }
      }
    } else if (auto name = scalar(entry, what)) {
      out.push_back(*name);
    }
    return out;
  }

  std::vector<RawReplace> replaces(const MapEntry& entry, const std::string& what) {
    std::vector<RawReplace> out;
    if (!map_value(entry, what)) return out;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      RawReplace replace;
      replace.node = item.key;
      replace.where = item.key_where;
      const std::string node_what = "replacement of node " + in_quotes(item.key);
      if (!map_value(item, node_what)) continue;
      for (const auto& part : map_entries(item.value, file_, diagnostics_)) {
        if (part.key == "stage") {
          replace.stage = scalar(part, "'stage' of " + node_what);
        } else if (part.key == "in") {
          replace.inputs_where = part.key_where;
          replace.inputs = inputs(part, "'in' of " + node_what);
        } else if (part.key == "params") {
          replace.params = settings(part, "'params' of " + node_what, /*check_names=*/false);
        } else {
          report_unknown_key(part, node_what, kReplaceKeys, diagnostics_);
        }
      }
      out.push_back(std::move(replace));
    }
    return out;
  }

  std::vector<RawSet> sets(const MapEntry& entry, const std::string& what) {
    std::vector<RawSet> out;
    if (!map_value(entry, what)) return out;
    for (const auto& item : map_entries(entry.value, file_, diagnostics_)) {
      const auto target = split_node_param(item.key);
      if (!target) {
        diagnostics_.error(item.key_where, "malformed key " + in_quotes(item.key) + " in " + what +
                                               ": expected 'node.param'");
        continue;
      }
      if (auto text = scalar(item, "parameter " + in_quotes(item.key))) {
        out.push_back({target->first,
                       item.key_where,
                       {target->second, text->text, text->where, true, text->text}});
      }
    }
    return out;
  }

  std::string file_;
  Diagnostics& diagnostics_;
};

}  // namespace

RawNode* RawGraph::find_node(const std::string& id) {
  const auto it =
      std::find_if(nodes.begin(), nodes.end(), [&](const RawNode& n) { return n.id == id; });
  return it == nodes.end() ? nullptr : &*it;
}

const RawVariant* RawGraph::find_variant(const std::string& variant_name) const {
  const auto it = std::find_if(variants.begin(), variants.end(),
                               [&](const RawVariant& v) { return v.name == variant_name; });
  return it == variants.end() ? nullptr : &*it;
}

std::vector<std::string> RawGraph::node_ids() const {
  std::vector<std::string> ids;
  for (const auto& node : nodes)
    ids.push_back(node.id);
  return ids;
}

std::vector<std::string> RawGraph::variant_names() const {
  std::vector<std::string> names;
  for (const auto& variant : variants)
    names.push_back(variant.name);
  return names;
}

RawGraph parse_graph_document(const YAML::Node& root, const std::string& file,
                              Diagnostics& diagnostics) {
  return DocumentReader(file, diagnostics).read(root);
}

std::optional<std::pair<std::string, std::string>> split_node_param(const std::string& text) {
  const std::size_t dot = text.find('.');
  if (dot == std::string::npos) return std::nullopt;
  std::string node = text.substr(0, dot);
  std::string param = text.substr(dot + 1);
  if (!is_identifier(node) || param.empty()) return std::nullopt;
  return std::make_pair(std::move(node), std::move(param));
}

}  // namespace facet::detail
