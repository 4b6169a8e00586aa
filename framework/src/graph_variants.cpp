#include "graph_variants.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include "yaml_checks.hpp"

namespace facet::detail {
namespace {

void check_node_reference(const RawGraph& graph, const std::string& node,
                          const SourceLocation& where, const std::string& context,
                          Diagnostics& diagnostics) {
  for (const auto& existing : graph.nodes) {
    if (existing.id == node) return;
  }
  diagnostics.error(where, "unknown node '" + node + "' in " + context +
                               suggestion_suffix(node, graph.node_ids(), ""));
}

// Depth-first walk over `extends`; `path` holds the variants being visited, so meeting one of
// them again is a cycle, reported once at the reference that closes it.
void check_extends_cycles(const RawGraph& graph, const RawVariant& variant,
                          std::vector<std::string>& path, std::set<std::string>& done,
                          Diagnostics& diagnostics) {
  if (done.count(variant.name) > 0) return;
  path.push_back(variant.name);
  for (const auto& base : variant.extends) {
    const auto on_path = std::find(path.begin(), path.end(), base.text);
    if (on_path != path.end()) {
      std::vector<std::string> cycle(on_path, path.end());
      cycle.push_back(base.text);
      diagnostics.error(base.where, "variant extends cycle: " + join(cycle, " -> "));
      continue;
    }
    if (const RawVariant* next = graph.find_variant(base.text)) {
      check_extends_cycles(graph, *next, path, done, diagnostics);
    }
  }
  path.pop_back();
  done.insert(variant.name);
}

void apply_replace(RawNode& node, const RawReplace& replace, const std::string& variant) {
  bool stage_changed = false;
  if (replace.stage) {
    stage_changed = !node.stage || node.stage->text != replace.stage->text;
    // Remember the stage written in the file, even when several variants replace it in turn.
    if (node.replaced_stage.empty() && node.stage) node.replaced_stage = node.stage->text;
    node.replaced_by_variant = variant;
    node.stage = replace.stage;
  }
  // The old parameters belong to the old stage: a new stage starts from its own defaults unless
  // the variant gives parameters.
  if (replace.params) {
    node.params = *replace.params;
  } else if (stage_changed) {
    node.params.clear();
  }
  if (replace.inputs) {
    node.inputs = *replace.inputs;
    node.inputs_where = replace.inputs_where;
  }
}

void apply_one(RawGraph& graph, const RawVariant& variant, std::set<std::string>& applied) {
  if (!applied.insert(variant.name).second) return;
  for (const auto& base : variant.extends) {
    if (const RawVariant* next = graph.find_variant(base.text)) apply_one(graph, *next, applied);
  }
  for (const auto& replace : variant.replaces) {
    if (RawNode* node = graph.find_node(replace.node)) apply_replace(*node, replace, variant.name);
  }
  for (const auto& set : variant.sets) {
    if (RawNode* node = graph.find_node(set.node)) set_param(*node, set.setting);
  }
}

}  // namespace

void check_variants(const RawGraph& graph, Diagnostics& diagnostics) {
  for (const auto& variant : graph.variants) {
    const std::string context = "variant '" + variant.name + "'";
    for (const auto& base : variant.extends) {
      if (graph.find_variant(base.text) == nullptr) {
        diagnostics.error(base.where, "unknown variant '" + base.text + "' in 'extends' of " +
                                          context +
                                          suggestion_suffix(base.text, graph.variant_names(), ""));
      }
    }
    for (const auto& replace : variant.replaces) {
      check_node_reference(graph, replace.node, replace.where, "'replace' of " + context,
                           diagnostics);
    }
    for (const auto& set : variant.sets) {
      check_node_reference(graph, set.node, set.key_where, "'set' of " + context, diagnostics);
    }
  }
  std::set<std::string> done;
  for (const auto& variant : graph.variants) {
    std::vector<std::string> path;
    check_extends_cycles(graph, variant, path, done, diagnostics);
  }
}

void apply_variant(RawGraph& graph, const std::string& name) {
  std::set<std::string> applied;
  // Applying edits only the nodes, so the variant pointers stay valid throughout.
  if (const RawVariant* variant = graph.find_variant(name)) apply_one(graph, *variant, applied);
}

void set_param(RawNode& node, ParamSetting setting) {
  const auto it = std::find_if(node.params.begin(), node.params.end(),
                               [&](const ParamSetting& p) { return p.name == setting.name; });
  if (it == node.params.end()) {
    node.params.push_back(std::move(setting));
  } else {
    *it = std::move(setting);
  }
}

}  // namespace facet::detail
