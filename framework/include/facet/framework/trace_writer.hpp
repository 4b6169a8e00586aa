#pragma once
// `facet run --trace FILE`: the run's stage calls in the Chrome trace event format (JSON), which
// chrome://tracing and https://ui.perfetto.dev open as a timeline: one row per thread, one slice
// per stage call, named by node, with the frame index and stage name as arguments.

#include <ostream>

#include "facet/framework/executor.hpp"

namespace facet {

// `stats` must come from a run with RunOptions::record_calls set.
void write_chrome_trace(std::ostream& out, const RunStats& stats, const std::string& graph_name);

}  // namespace facet
