#include "graph_variants.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
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

// Position of every variant by name; the first of two equal names wins, as in find_variant.
std::unordered_map<std::string, std::size_t> variant_positions(const RawGraph& graph) {
  std::unordered_map<std::string, std::size_t> positions;
  for (std::size_t i = 0; i < graph.variants.size(); ++i)
    positions.emplace(graph.variants[i].name, i);
  return positions;
}

// "a -> b -> c -> a", with the middle of a long cycle left out.
std::string cycle_text(const std::vector<std::string>& cycle) {
  constexpr std::size_t kShown = 8;
  if (cycle.size() <= kShown) return join(cycle, " -> ");
  const std::vector<std::string> head(cycle.begin(), cycle.begin() + kShown / 2);
  const std::vector<std::string> tail(cycle.end() - kShown / 2, cycle.end());
  return join(head, " -> ") + " -> ... (" + std::to_string(cycle.size() - kShown) + " more) -> " +
         join(tail, " -> ");
}

// Where a depth-first walk over `extends` is: the variant and the next of its bases to visit.
// The walks below keep their own stack, so that a chain of 100 000 variants neither overflows
// the call stack nor takes quadratic time.
struct ExtendsFrame {
  std::size_t variant;
  std::size_t next_base = 0;
};

// Meeting a variant that is on the walk's path again is a cycle, reported once at the reference
// that closes it.
void check_extends_cycles(const RawGraph& graph, Diagnostics& diagnostics) {
  enum class Visit { unseen, on_path, done };
  const auto positions = variant_positions(graph);
  std::vector<Visit> visit(graph.variants.size(), Visit::unseen);
  std::vector<std::size_t> depth_of(graph.variants.size(), 0);
  for (std::size_t root = 0; root < graph.variants.size(); ++root) {
    if (visit[root] != Visit::unseen) continue;
    std::vector<ExtendsFrame> path{{root}};
    visit[root] = Visit::on_path;
    while (!path.empty()) {
      ExtendsFrame& top = path.back();
      const RawVariant& variant = graph.variants[top.variant];
      if (top.next_base == variant.extends.size()) {
        visit[top.variant] = Visit::done;
        path.pop_back();
        continue;
      }
      const auto& base = variant.extends[top.next_base++];
      const auto found = positions.find(base.text);
      if (found == positions.end()) continue;  // reported by check_variants
      const std::size_t next = found->second;
      if (visit[next] == Visit::on_path) {
        std::vector<std::string> cycle;
        for (std::size_t i = depth_of[next]; i < path.size(); ++i)
          cycle.push_back(graph.variants[path[i].variant].name);
        cycle.push_back(base.text);
        diagnostics.error(base.where, "variant extends cycle: " + cycle_text(cycle));
      } else if (visit[next] == Visit::unseen) {
        visit[next] = Visit::on_path;
        depth_of[next] = path.size();
        path.push_back({next});
      }
    }
  }
}

void apply_edits(RawGraph& graph, const RawVariant& variant) {
  for (const auto& replace : variant.replaces) {
    if (RawNode* node = graph.find_node(replace.node)) apply_replace(*node, replace, variant.name);
  }
  for (const auto& set : variant.sets) {
    if (RawNode* node = graph.find_node(set.node)) set_param(*node, set.setting);
  }
}

}  // namespace

void check_variants(const RawGraph& graph, Diagnostics& diagnostics) {
  const auto positions = variant_positions(graph);
  for (const auto& variant : graph.variants) {
    const std::string context = "variant '" + variant.name + "'";
    for (const auto& base : variant.extends) {
      if (positions.count(base.text) == 0) {
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
  check_extends_cycles(graph, diagnostics);
}

void apply_variant(RawGraph& graph, const std::string& name) {
  const auto positions = variant_positions(graph);
  const auto start = positions.find(name);
  if (start == positions.end()) return;
  // Bases first, in the order `extends` lists them, each variant once; then the variant itself.
  // Applying edits only the nodes, so the variants stay as they are throughout.
  std::vector<bool> applied(graph.variants.size(), false);
  std::vector<ExtendsFrame> path{{start->second}};
  applied[start->second] = true;
  while (!path.empty()) {
    ExtendsFrame& top = path.back();
    const RawVariant& variant = graph.variants[top.variant];
    if (top.next_base == variant.extends.size()) {
      apply_edits(graph, variant);
      path.pop_back();
      continue;
    }
    const auto found = positions.find(variant.extends[top.next_base++].text);
    if (found == positions.end() || applied[found->second]) continue;
    applied[found->second] = true;
    path.push_back({found->second});
  }
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
