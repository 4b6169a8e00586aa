#include "stage_lines.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace facet::cli {

void write_stage_lines(std::ostream& out, const std::vector<const StageEntry*>& stages,
                       const std::string& indent) {
  std::size_t name_width = 0;
  std::size_t plugin_width = 16;  // the column stays where it was for the usual plugin names
  for (const StageEntry* entry : stages) {
    name_width = std::max(name_width, entry->spec.name().size());
    plugin_width = std::max(plugin_width, entry->plugin->name.size());
  }
  for (const StageEntry* entry : stages) {
    out << fmt::format("{}{:<{}}  {:<{}} {}\n", indent, entry->spec.name(), name_width,
                       entry->plugin->name, plugin_width, entry->spec.summary());
  }
}

std::string did_you_mean_text(const std::vector<std::string>& suggestions) {
  if (suggestions.empty()) return {};
  std::string text = "; did you mean ";
  for (std::size_t i = 0; i < suggestions.size(); ++i) {
    if (i > 0) text += i + 1 == suggestions.size() ? " or " : ", ";
    text += "'" + suggestions[i] + "'";
  }
  return text + "?";
}

}  // namespace facet::cli
