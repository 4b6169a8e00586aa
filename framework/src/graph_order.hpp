#pragma once
// Ordering the nodes of a graph: cycles with their full path, and a topological order.

#include <cstddef>
#include <vector>

#include "facet/framework/diagnostics.hpp"

namespace facet::detail {

// Node `from` feeds node `to`; `where` is the input reference that says so.
struct Dependency {
  std::size_t from = 0;
  std::size_t to = 0;
  SourceLocation where;
};

struct Cycle {
  std::vector<std::size_t> path;  // first == last: a -> b -> a
  SourceLocation where;           // the reference that closes the cycle
};

// Every cycle that a depth-first search meets (one per back edge), in a deterministic order:
// nodes and their inputs are visited in file order.
std::vector<Cycle> find_cycles(std::size_t node_count, const std::vector<Dependency>& edges);

// Producers before consumers; among nodes that are ready at the same time, the one written first
// in the file comes first. Nodes on a cycle are appended at the end in file order.
std::vector<std::size_t> topological_order(std::size_t node_count,
                                           const std::vector<Dependency>& edges);

}  // namespace facet::detail
