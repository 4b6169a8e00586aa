#pragma once
// Variants: named edits of a graph (`replace:` a node's stage, `set:` parameters), which may
// extend other variants.

#include <string>

#include "facet/framework/diagnostics.hpp"
#include "graph_document.hpp"

namespace facet::detail {

// Checks every variant of the file, selected or not: the nodes it names exist, the variants it
// extends exist, and `extends` has no cycle.
void check_variants(const RawGraph& graph, Diagnostics& diagnostics);

// Applies variant `name` (which must exist) to the graph's nodes: the variants it extends first,
// in the order listed, each once; then its own `replace:`, then its own `set:`.
void apply_variant(RawGraph& graph, const std::string& name);

// Replaces the node's stage, inputs or params with those `replace` gives. A new stage without
// params of its own starts from its defaults. `variant` (empty for other edits) is remembered for
// the note that explains a port error.
void apply_replace(RawNode& node, const RawReplace& replace, const std::string& variant);

// Sets `setting` on node `node`: replaces a setting of the same name or appends one.
void set_param(RawNode& node, ParamSetting setting);

}  // namespace facet::detail
