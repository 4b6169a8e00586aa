#pragma once
// The documentation of a stage as `facet inspect` prints it, in plain text for a terminal or in
// Markdown for docs/ (so the stage reference is generated from the same declarations).

#include <ostream>
#include <string>

#include "facet/framework/registry.hpp"

namespace facet {

// "int, default 3, one of {3, 5}, px" — the one-line summary of a parameter's declaration.
std::string describe_param(const ParamSpec& param);

void write_stage_text(std::ostream& out, const StageEntry& entry);
void write_stage_markdown(std::ostream& out, const StageEntry& entry);

}  // namespace facet
