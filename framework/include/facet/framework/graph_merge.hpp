#pragma once
// Merging variants of one graph into a single graph, for A/B comparison (`facet compare`): a node
// that is the same in several variants — same stage, same parameters, and inputs fed by nodes
// that are themselves the same — appears once and runs once per frame for all of them, so every
// variant sees identical input; a node that differs anywhere upstream gets one copy per distinct
// version, named `<id>@<variant>` (or `<id>@<a>+<b>` when variants a and b share that version).

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "facet/framework/graph_spec.hpp"

namespace facet {

struct VariantGraph {
  std::string name;  // as shown in reports and node suffixes
  GraphSpec spec;    // the graph loaded with this variant applied
};

struct MergeOptions {
  // Nodes for which this returns true are never shared, even when identical: each variant gets
  // its own copy (e.g. sinks, so that each variant writes its own files).
  std::function<bool(const NodeSpec&)> keep_per_variant;
};

struct MergedVariant {
  std::string name;
  std::map<std::string, std::string> node_ids;  // the variant's node id -> id in the merged graph
};

struct MergedGraph {
  GraphSpec spec;  // file, name, params and plugin paths of the first variant; the merged nodes
  std::vector<MergedVariant> variants;  // in the order given
  // Merged node id -> names of the variants that run it (one for a private node).
  std::map<std::string, std::vector<std::string>> users;

  bool is_shared(const std::string& merged_id) const;
};

// Merges `variants` (at least one; every spec should define the same node ids, as variants of
// one file do). Node order: the first variant's file order, each node's versions in variant
// order, so that the variants' private branches interleave stage by stage. Throws
// std::invalid_argument for an empty list or duplicate variant names.
MergedGraph merge_variants(const std::vector<VariantGraph>& variants,
                           const MergeOptions& options = {});

}  // namespace facet
