#pragma once
// The sweep's parts of the text reports (compare_report.hpp): what the terminal prints after the
// table, and the "sweep" fields of compare.json.

#include <cstddef>
#include <ostream>

#include "facet/framework/json_writer.hpp"
#include "facet/framework/sweep_summary.hpp"

namespace facet::detail {

// The grid, the best point of each score and the headline score's plateau along each axis.
void write_sweep_findings(std::ostream& out, const SweepSummary& sweep);

// {"node.param": value, ...} of point `point`: integers for integral axes.
void write_sweep_point_json(JsonWriter& json, const SweepSummary& sweep, std::size_t point);

// {"variant", "params", "headline", "within", "best", "plateau"}
void write_sweep_json(JsonWriter& json, const SweepSummary& sweep);

}  // namespace facet::detail
