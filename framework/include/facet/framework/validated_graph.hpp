#pragma once
// A graph checked against the registry: every node's stage exists, its parameters are typed and in
// range, every connection joins ports of the same type, every required input is connected and
// there is no cycle. Nodes are in topological order (planned with Boost.Graph).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "facet/framework/diagnostics.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/registry.hpp"

namespace facet {

struct Connection {
  std::size_t from_node = 0;  // index into ValidatedGraph::nodes
  std::size_t from_port = 0;  // index into that node's spec outputs
};

struct ValidatedNode {
  std::string id;
  const StageEntry* stage = nullptr;  // owned by the Registry, which must outlive the graph
  Params params;
  // One entry per input port of the stage, in the spec's order; nullopt = unconnected optional.
  std::vector<std::optional<Connection>> inputs;
  SourceLocation where;
};

// A graph input or output (GraphPort) resolved to the output port it names.
struct ValidatedGraphPort {
  std::string name;
  Connection port;       // the node (index into ValidatedGraph::nodes) and its output
  std::string type_key;  // of that output
  SourceLocation where;
};

struct ValidatedGraph {
  std::string name;
  std::filesystem::path file;
  std::vector<ValidatedNode> nodes;  // topological order: producers before consumers
  std::vector<ValidatedGraphPort> inputs;
  std::vector<ValidatedGraphPort> outputs;

  const ValidatedNode* find(const std::string& id) const;
};

// Checks `graph` against `registry`, reporting every problem into `diagnostics`.
ValidatedGraph validate_graph(const GraphSpec& graph, const Registry& registry,
                              Diagnostics& diagnostics);

}  // namespace facet
