#pragma once
// Shared helpers for the graph tests: load YAML text under a fixed display name.

#include <gtest/gtest.h>

#include <facet/framework/graph_spec.hpp>
#include <string>

namespace facet::graph_test {

inline GraphSpec load(const std::string& yaml, Diagnostics& diagnostics,
                      const LoadOptions& options = {}) {
  return load_graph_text(yaml, "g.yaml", options, diagnostics);
}

// The text of the only error, or a failure naming all of them.
inline std::string single_error(const Diagnostics& diagnostics) {
  std::string found;
  int errors = 0;
  for (const auto& item : diagnostics.all()) {
    if (item.severity != Severity::error) continue;
    ++errors;
    found = format_location(item.where) + ": " + item.message;
  }
  if (errors != 1) {
    ADD_FAILURE() << "expected exactly one error, got " << errors << ":\n" << diagnostics.str();
  }
  return found;
}

inline const ParamSetting* find_param(const NodeSpec& node, const std::string& name) {
  return node.find_param(name);
}

}  // namespace facet::graph_test
