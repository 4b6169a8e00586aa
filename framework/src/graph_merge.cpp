#include "facet/framework/graph_merge.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace facet {
namespace {

// Identifies a node's version by what determines its output: stage, parameters and the
// versions of the nodes that feed it. Versions are interned as small numbers, so a signature
// stays short however deep the graph is.
class VersionTable {
 public:
  int version_of(const std::string& key) {
    return table_.try_emplace(key, static_cast<int>(table_.size())).first->second;
  }

 private:
  std::map<std::string, int> table_;
};

class VariantVersions {
 public:
  VariantVersions(const VariantGraph& variant, const MergeOptions& options, VersionTable& table)
      : variant_(variant), options_(options), table_(table) {}

  int of(const std::string& id) {
    if (const auto it = versions_.find(id); it != versions_.end()) return it->second;
    const NodeSpec* node = variant_.spec.find_node(id);
    // A missing node or a cycle is left to validation; here it only must not be shared.
    if (node == nullptr || !visiting_.insert(id).second) return table_.version_of("?" + id);
    std::vector<std::string> params;
    for (const auto& param : node->params)
      params.push_back(param.name + "=" + param.text);
    std::sort(params.begin(), params.end());
    std::vector<std::string> inputs;
    for (const auto& input : node->inputs) {
      inputs.push_back(input.port + "<" + std::to_string(of(input.from_node)) + "." +
                       input.from_port);
    }
    std::sort(inputs.begin(), inputs.end());
    std::string key = node->stage;
    for (const auto& part : params)
      key += '\n' + part;
    key += "\n--";
    for (const auto& part : inputs)
      key += '\n' + part;
    // A private copy is a version of its own, and so is everything downstream of it.
    if (options_.keep_per_variant && options_.keep_per_variant(*node)) {
      key += "\n#" + variant_.name;
    }
    visiting_.erase(id);
    return versions_[id] = table_.version_of(key);
  }

 private:
  const VariantGraph& variant_;
  const MergeOptions& options_;
  VersionTable& table_;
  std::map<std::string, int> versions_;
  std::set<std::string> visiting_;
};

std::string joined(const std::vector<std::string>& names, char separator) {
  std::string text;
  for (const auto& name : names) {
    if (!text.empty()) text += separator;
    text += name;
  }
  return text;
}

}  // namespace

bool MergedGraph::is_shared(const std::string& merged_id) const {
  const auto it = users.find(merged_id);
  return it != users.end() && it->second.size() > 1;
}

MergedGraph merge_variants(const std::vector<VariantGraph>& variants, const MergeOptions& options) {
  if (variants.empty()) throw std::invalid_argument("merge_variants: no variant given");
  std::set<std::string> names;
  for (const auto& variant : variants) {
    if (!names.insert(variant.name).second) {
      throw std::invalid_argument("variant '" + variant.name + "' is given twice");
    }
  }

  VersionTable table;
  std::vector<VariantVersions> versions;
  versions.reserve(variants.size());
  for (const auto& variant : variants)
    versions.emplace_back(variant, options, table);

  MergedGraph merged;
  merged.spec = variants.front().spec;
  merged.spec.nodes.clear();
  // Graph ports are for a program feeding one variant (docs/embedding.md); they name nodes by
  // their own ids, which the merge renames.
  merged.spec.inputs.clear();
  merged.spec.outputs.clear();
  std::vector<std::string> variant_names;
  for (const auto& variant : variants) {
    merged.variants.push_back({variant.name, {}});
    variant_names.push_back(variant.name);
  }
  merged.spec.variant = joined(variant_names, ',');

  // Node ids in the first variant's file order, then any that only later variants have.
  std::vector<std::string> ids;
  for (const auto& variant : variants) {
    for (const auto& node : variant.spec.nodes) {
      if (std::find(ids.begin(), ids.end(), node.id) == ids.end()) ids.push_back(node.id);
    }
  }

  // First pass: which variants share which version of each node, and the merged ids.
  struct Version {
    std::vector<std::size_t> variants;  // indices of the variants that run it
    std::string merged_id;
  };
  std::map<std::string, std::vector<Version>> versions_of_node;
  for (const auto& id : ids) {
    std::vector<Version> node_versions;
    std::map<int, std::size_t> by_version;
    std::size_t present = 0;
    for (std::size_t v = 0; v < variants.size(); ++v) {
      const NodeSpec* node = variants[v].spec.find_node(id);
      if (node == nullptr) continue;
      ++present;
      const int version = versions[v].of(id);
      const auto [it, inserted] = by_version.try_emplace(version, node_versions.size());
      if (inserted) node_versions.push_back({});
      node_versions[it->second].variants.push_back(v);
    }
    const bool one_for_all = node_versions.size() == 1 && present == variants.size();
    for (auto& version : node_versions) {
      std::vector<std::string> users;
      for (const std::size_t v : version.variants)
        users.push_back(variants[v].name);
      version.merged_id = one_for_all ? id : id + "@" + joined(users, '+');
      merged.users[version.merged_id] = users;
      for (const std::size_t v : version.variants)
        merged.variants[v].node_ids[id] = version.merged_id;
    }
    versions_of_node[id] = std::move(node_versions);
  }

  // Second pass: one node per version, its inputs renamed to the versions that feed it.
  for (const auto& id : ids) {
    for (const auto& version : versions_of_node[id]) {
      const std::size_t v = version.variants.front();
      NodeSpec node = *variants[v].spec.find_node(id);
      node.id = version.merged_id;
      for (auto& input : node.inputs) {
        const auto& renamed = merged.variants[v].node_ids;
        if (const auto it = renamed.find(input.from_node); it != renamed.end()) {
          input.from_node = it->second;
        }
      }
      merged.spec.nodes.push_back(std::move(node));
    }
  }
  return merged;
}

}  // namespace facet
