#pragma once
// `facet run --view`: watch a run in a window without editing its graph.

#include "facet/framework/diagnostics.hpp"
#include "facet/framework/graph_spec.hpp"

namespace facet::cli {

// Adds a node `view` (io.view) showing the graph's depth input over its labels output: the
// ports `inputs: {depth: ...}` and `outputs: {labels: ...}` that a graph declares for programs
// (docs/embedding.md) say where they are. A graph without them is an error saying so.
void add_view_node(GraphSpec& graph, Diagnostics& diagnostics);

}  // namespace facet::cli
