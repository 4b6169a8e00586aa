#include "graph_substitution.hpp"

#include <vector>

#include "yaml_checks.hpp"

namespace facet::detail {

std::optional<std::string> ParamSubstitution::expand(const std::string& text,
                                                     const SourceLocation& where,
                                                     Diagnostics& diagnostics) const {
  std::string out;
  bool ok = true;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t open = text.find("${", pos);
    if (open == std::string::npos) {
      out.append(text, pos, std::string::npos);
      break;
    }
    out.append(text, pos, open - pos);
    const std::size_t close = text.find('}', open + 2);
    if (close == std::string::npos) {
      diagnostics.error(where, "unterminated '${' in '" + text + "'");
      return std::nullopt;
    }
    const std::string name = text.substr(open + 2, close - open - 2);
    const auto it = values_.find(name);
    if (it == values_.end()) {
      std::vector<std::string> names;
      for (const auto& [known, value] : values_)
        names.push_back(known);
      diagnostics.error(where, "undefined graph parameter '${" + name + "}'" +
                                   suggestion_suffix(name, names, "defined are"));
      ok = false;
    } else if (open == 0 && close + 1 < text.size() && text[close + 1] == '/' &&
               it->second.find_first_not_of('/') == std::string::npos) {
      // `--param output=` (or `=/`) would turn '${output}/labels' into '/labels': files written
      // at the top of the filesystem, which nobody asks for this way.
      diagnostics.error(where, "graph parameter '" + name + "' is " +
                                   (it->second.empty() ? "empty" : "'" + it->second + "'") +
                                   ", which makes '" + text +
                                   "' a path at the filesystem root; "
                                   "give it a folder (--param " +
                                   name + "=DIR)");
      ok = false;
    } else {
      out += it->second;
    }
    pos = close + 1;
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace facet::detail
