#include "view_option.hpp"

#include <algorithm>
#include <string>

namespace facet::cli {
namespace {

constexpr const char* kViewNode = "view";

const GraphPort* find_port(const std::vector<GraphPort>& ports, const std::string& name) {
  const auto it = std::find_if(ports.begin(), ports.end(),
                               [&](const GraphPort& port) { return port.name == name; });
  return it == ports.end() ? nullptr : &*it;
}

}  // namespace

void add_view_node(GraphSpec& graph, Diagnostics& diagnostics) {
  const SourceLocation option{kCommandLineFile, 0, 0};
  const GraphPort* depth = find_port(graph.inputs, "depth");
  const GraphPort* labels = find_port(graph.outputs, "labels");
  if (depth == nullptr || labels == nullptr) {
    diagnostics.error(
        option,
        "--view shows the graph's depth and labels, but " + graph.file.string() + " declares no " +
            (depth == nullptr ? "'inputs: {depth: node.port}'" : "'outputs: {labels: node.port}'") +
            " (docs/graph-format.md); add an io.view node instead");
    return;
  }
  if (graph.find_node(kViewNode) != nullptr) {
    diagnostics.error(option, std::string("--view adds a node '") + kViewNode +
                                  "', but the graph has one already");
    return;
  }
  NodeSpec view;
  view.id = kViewNode;
  view.stage = "io.view";
  view.where = option;
  view.stage_where = option;
  view.inputs = {{"depth", depth->node, depth->port, option},
                 {"labels", labels->node, labels->port, option}};
  const std::string title = "facet run " + graph.name;
  view.params = {{"title", title, option, true, title}};
  graph.nodes.push_back(std::move(view));
}

}  // namespace facet::cli
