#pragma once
// The documentation of a stage as `facet inspect` prints it, in plain text for a terminal or in
// Markdown for docs/ (so the stage reference is generated from the same declarations).

#include <ostream>
#include <string>

#include "facet/framework/json_writer.hpp"
#include "facet/framework/registry.hpp"

namespace facet {

// "int, default 3, one of {3, 5}, px" — the one-line summary of a parameter's declaration.
std::string describe_param(const ParamSpec& param);

void write_stage_text(std::ostream& out, const StageEntry& entry);
void write_stage_markdown(std::ostream& out, const StageEntry& entry);

// The spec as one JSON object, for tools (`facet inspect --json`): name, summary, doc, plugin,
// concurrency, ports with their type keys, parameters with type, typed default, range, choices,
// unit, doc and the default's origin. Absent attributes are null, so every key is always there.
void write_stage_json(JsonWriter& json, const StageEntry& entry);

}  // namespace facet
