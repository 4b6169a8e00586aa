#include "facet/framework/dot_writer.hpp"

#include <string>

namespace facet {
namespace {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

}  // namespace

void write_dot(std::ostream& out, const ValidatedGraph& graph) {
  out << "digraph " << quoted(graph.name) << " {\n";
  out << "  rankdir=LR;\n  node [shape=box, style=rounded, fontname=\"Helvetica\"];\n";
  out << "  edge [fontname=\"Helvetica\", fontsize=10];\n";
  for (const auto& node : graph.nodes) {
    out << "  " << quoted(node.id) << " [label=" << quoted(node.id + "\n" + node.stage->spec.name())
        << "];\n";
  }
  for (const auto& node : graph.nodes) {
    const auto& inputs = node.stage->spec.inputs();
    for (std::size_t port = 0; port < node.inputs.size(); ++port) {
      if (!node.inputs[port]) continue;
      const auto& from = graph.nodes[node.inputs[port]->from_node];
      const auto& from_port = from.stage->spec.outputs()[node.inputs[port]->from_port];
      out << "  " << quoted(from.id) << " -> " << quoted(node.id) << " [label="
          << quoted(from_port.name + " → " + inputs[port].name + "\n" + from_port.type_key)
          << "];\n";
    }
  }
  out << "}\n";
}

}  // namespace facet
