#pragma once
// One line per stage (name, plugin, one-line summary), as `facet list` and `facet inspect FAMILY`
// print them, and the "did you mean" tail for a name that matched nothing.

#include <ostream>
#include <string>
#include <vector>

#include "facet/framework/registry.hpp"

namespace facet::cli {

// Names and plugins are padded to the longest of `stages`, so the columns line up.
void write_stage_lines(std::ostream& out, const std::vector<const StageEntry*>& stages,
                       const std::string& indent = {});

// "; did you mean 'a'?" or "; did you mean 'a', 'b' or 'c'?"; empty without suggestions.
std::string did_you_mean_text(const std::vector<std::string>& suggestions);

}  // namespace facet::cli
