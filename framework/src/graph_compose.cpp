#include "graph_compose.hpp"

#include <algorithm>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "graph_variants.hpp"
#include "yaml_checks.hpp"

namespace facet::detail {
namespace {

namespace fs = std::filesystem;

// Deeper chains are almost surely a mistake; the bound keeps a runaway chain cheap.
constexpr std::size_t kMaxExtendsDepth = 32;

const std::string kGraphDirReference = "${graph_dir}";

// Two spellings of one file compare equal once made canonical; a file that does not exist keeps
// its normalised absolute path.
fs::path identity_of(const fs::path& file) {
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(fs::absolute(file, error), error);
  return error ? file.lexically_normal() : canonical;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
    text.replace(at, from.size(), to);
    at += to.size();
  }
}

// `${graph_dir}` in a base means the base's directory, whichever file extends it: written in
// before the chain is folded, when every scalar still knows which file it came from.
class GraphDirPinner {
 public:
  explicit GraphDirPinner(const fs::path& dir) : dir_(dir.generic_string()) {}

  void pin(RawGraph& graph) const {
    for (auto& param : graph.params)
      pin(param.text);
    for (auto& path : graph.plugin_paths) {
      pin(path.text);
      // Relative plugin paths are relative to the base's file too.
      const fs::path given(path.text);
      if (!given.is_relative() || path.text.find("${") != std::string::npos) continue;
      path.text = (fs::path(dir_) / given).lexically_normal().generic_string();
    }
    for (auto& node : graph.nodes)
      pin(node);
    for (auto& port : graph.graph_inputs)
      pin(port.ref.text);
    for (auto& port : graph.graph_outputs)
      pin(port.ref.text);
    for (auto& variant : graph.variants) {
      for (auto& replace : variant.replaces)
        pin(replace);
      for (auto& set : variant.sets)
        pin(set.setting.text);
    }
    for (auto& replace : graph.replaces)
      pin(replace);
    for (auto& set : graph.sets)
      pin(set.setting.text);
  }

 private:
  void pin(std::string& text) const { replace_all(text, kGraphDirReference, dir_); }

  void pin(std::vector<RawInput>& inputs) const {
    for (auto& input : inputs)
      pin(input.ref.text);
  }

  void pin(std::vector<ParamSetting>& params) const {
    for (auto& param : params)
      pin(param.text);
  }

  void pin(RawNode& node) const {
    if (node.stage) pin(node.stage->text);
    pin(node.inputs);
    pin(node.params);
  }

  void pin(RawReplace& replace) const {
    if (replace.stage) pin(replace.stage->text);
    if (replace.inputs) pin(*replace.inputs);
    if (replace.params) pin(*replace.params);
  }

  std::string dir_;
};

RawNode* find_reported(RawGraph& graph, const std::string& id, const SourceLocation& where,
                       const std::string& context, Diagnostics& diagnostics) {
  if (RawNode* node = graph.find_node(id)) return node;
  diagnostics.error(where, "unknown node " + in_quotes(id) + " in " + context +
                               " of the base graph" + suggestion_suffix(id, graph.node_ids(), ""));
  return nullptr;
}

void remove_nodes(RawGraph& graph, const std::vector<RawText>& removes,
                  const std::string& derived_file, Diagnostics& diagnostics) {
  for (const RawText& remove : removes) {
    const std::string& id = remove.text;
    if (find_reported(graph, id, remove.where, "'remove'", diagnostics) == nullptr) continue;
    std::erase_if(graph.nodes, [&id](const RawNode& node) { return node.id == id; });
    graph.removed.push_back({id, "'remove:' of " + derived_file + " takes it out", remove.where,
                             "node " + in_quotes(id) + " removed here"});
  }
}

// Graph ports the derived file does not redefine stay, unless they read a removed node.
void keep_ports(std::vector<RawInput>& ports, const RawGraph& graph) {
  std::erase_if(ports, [&](const RawInput& port) {
    const std::string node = port.ref.text.substr(0, port.ref.text.find('.'));
    return std::any_of(graph.removed.begin(), graph.removed.end(),
                       [&](const LeftOutNode& removed) { return removed.id == node; });
  });
}

bool names_a_missing_node(const RawVariant& variant, const RawGraph& graph) {
  const auto missing = [&](const std::string& id) {
    return std::none_of(graph.nodes.begin(), graph.nodes.end(),
                        [&](const RawNode& node) { return node.id == id; });
  };
  return std::any_of(variant.replaces.begin(), variant.replaces.end(),
                     [&](const RawReplace& replace) { return missing(replace.node); }) ||
         std::any_of(variant.sets.begin(), variant.sets.end(),
                     [&](const RawSet& set) { return missing(set.node); });
}

// The base's variants that still make sense here (they edit no removed node), that the derived
// file does not remove and does not redefine; then the derived file's own.
std::vector<RawVariant> merged_variants(const RawGraph& base_with_edits,
                                        std::vector<RawVariant> derived,
                                        const std::vector<RawText>& removed,
                                        Diagnostics& diagnostics) {
  const auto base_names = base_with_edits.variant_names();
  for (const auto& [name, where] : removed) {
    if (std::find(base_names.begin(), base_names.end(), name) == base_names.end()) {
      diagnostics.error(where, "unknown variant " + in_quotes(name) +
                                   " in 'remove_variants' of the base graph" +
                                   suggestion_suffix(name, base_names, ""));
    }
  }
  std::vector<RawVariant> out;
  for (const auto& variant : base_with_edits.variants) {
    const auto named = [&](const auto& other) { return other.name == variant.name; };
    const bool redefined = std::any_of(derived.begin(), derived.end(), named);
    const bool dropped = std::any_of(removed.begin(), removed.end(), [&](const RawText& name) {
      return name.text == variant.name;
    });
    if (!redefined && !dropped && !names_a_missing_node(variant, base_with_edits)) {
      out.push_back(variant);
    }
  }
  for (auto& variant : derived)
    out.push_back(std::move(variant));
  return out;
}

// Graph params: the base's, each default replaced by the derived file's where it gives one,
// then the derived file's new ones.
std::vector<ParamSetting> merged_params(std::vector<ParamSetting> base,
                                        const std::vector<ParamSetting>& derived) {
  for (const auto& param : derived) {
    const auto it = std::find_if(base.begin(), base.end(),
                                 [&](const ParamSetting& own) { return own.name == param.name; });
    if (it == base.end()) {
      base.push_back(param);
    } else {
      *it = param;
    }
  }
  return base;
}

// `derived` applied to `base`: the one graph the two files describe.
RawGraph fold(RawGraph base, RawGraph derived, const std::string& derived_file,
              Diagnostics& diagnostics) {
  RawGraph out = std::move(base);
  out.extends.reset();
  out.name = derived.name;
  if (!derived.description.empty()) out.description = derived.description;
  out.params = merged_params(std::move(out.params), derived.params);
  for (auto& path : derived.plugin_paths)
    out.plugin_paths.push_back(std::move(path));

  remove_nodes(out, derived.removes, derived_file, diagnostics);
  for (const auto& replace : derived.replaces) {
    if (RawNode* node = find_reported(out, replace.node, replace.where, "'replace'", diagnostics)) {
      apply_replace(*node, replace, "");
    }
  }
  for (auto& set : derived.sets) {
    if (RawNode* node = find_reported(out, set.node, set.key_where, "'set'", diagnostics)) {
      set_param(*node, std::move(set.setting));
    }
  }
  for (auto& node : derived.nodes) {
    if (const RawNode* existing = out.find_node(node.id)) {
      diagnostics.error(node.where, "node " + in_quotes(node.id) +
                                        " is already in the base graph; change it with "
                                        "'replace:' or 'set:', or give this node another id");
      diagnostics.note(existing->where, "the base graph's node " + in_quotes(node.id));
      continue;
    }
    out.nodes.push_back(std::move(node));
  }

  if (derived.has_graph_inputs) {
    out.graph_inputs = std::move(derived.graph_inputs);
  } else {
    keep_ports(out.graph_inputs, out);
  }
  if (derived.has_graph_outputs) {
    out.graph_outputs = std::move(derived.graph_outputs);
  } else {
    keep_ports(out.graph_outputs, out);
  }
  out.variants =
      merged_variants(out, std::move(derived.variants), derived.removed_variants, diagnostics);
  if (derived.headline) out.headline = std::move(derived.headline);
  return out;
}

}  // namespace

fs::path absolute_dir_of(const fs::path& file) {
  std::error_code error;
  fs::path absolute = fs::absolute(file, error);
  if (error) absolute = file;
  return absolute.lexically_normal().parent_path();
}

void resolve_extends(RawGraph& graph, const fs::path& file, const BaseGraphReader& read_base,
                     Diagnostics& diagnostics) {
  if (!graph.extends) return;
  // The chain from this file down to its last base; read first, folded from the bottom up.
  std::vector<RawGraph> chain;
  std::vector<fs::path> files{file};
  chain.push_back(std::move(graph));
  while (chain.back().extends) {
    const RawText extends = *chain.back().extends;
    chain.back().extends.reset();
    const fs::path given(extends.text);
    const fs::path base_file =
        given.is_absolute() ? given : (absolute_dir_of(files.back()) / given).lexically_normal();
    const auto same = [&](const fs::path& seen) {
      return identity_of(seen) == identity_of(base_file);
    };
    if (std::any_of(files.begin(), files.end(), same)) {
      diagnostics.error(extends.where, "graph extends cycle: " + in_quotes(base_file.string()) +
                                           " extends, "
                                           "through its bases, the file that extends it");
      break;
    }
    if (chain.size() > kMaxExtendsDepth) {
      diagnostics.error(extends.where, "graph extends chain deeper than " +
                                           std::to_string(kMaxExtendsDepth) + " files");
      break;
    }
    diagnostics.add_file_context(base_file.string(), extends.where,
                                 "in the base graph of " + files.back().string());
    std::optional<RawGraph> base = read_base(base_file, extends.where);
    if (!base) break;
    GraphDirPinner(absolute_dir_of(base_file)).pin(*base);
    chain.push_back(std::move(*base));
    files.push_back(base_file);
  }
  RawGraph folded = std::move(chain.back());
  folded.extends.reset();
  for (std::size_t i = chain.size() - 1; i-- > 0;) {
    folded = fold(std::move(folded), std::move(chain[i]), files[i].string(), diagnostics);
  }
  graph = std::move(folded);
}

}  // namespace facet::detail
