#pragma once
// ${name} references in graph scalars: replaced by graph parameters and built-ins (${graph_dir}).

#include <map>
#include <optional>
#include <string>

#include "facet/framework/diagnostics.hpp"

namespace facet::detail {

// The built-in parameter: the directory of the graph file.
inline constexpr const char* kGraphDirParam = "graph_dir";

class ParamSubstitution {
 public:
  explicit ParamSubstitution(std::map<std::string, std::string> values)
      : values_(std::move(values)) {}

  // `text` with every ${name} replaced. Reports each undefined name or unterminated `${` at
  // `where` (the scalar's location) and returns nothing if there was any.
  std::optional<std::string> expand(const std::string& text, const SourceLocation& where,
                                    Diagnostics& diagnostics) const;

 private:
  std::map<std::string, std::string> values_;
};

}  // namespace facet::detail
