#pragma once

#include <ostream>

#include "facet/framework/validated_graph.hpp"

namespace facet {

// Graphviz text of a validated graph: one box per node (id and stage), one edge per connection,
// labelled with the ports and the type carried.
void write_dot(std::ostream& out, const ValidatedGraph& graph);

}  // namespace facet
