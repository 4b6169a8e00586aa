#pragma once
// Reports of a finished run: the per-stage timing table of `facet run --profile` and the
// machine-readable statistics of `facet run --json`.

#include <ostream>
#include <string>

#include "facet/framework/executor.hpp"

namespace facet {

// {"graph": ..., "variant": ..., "frames": N,
//  "stages": {"<node id>": {"stage": ..., "calls": n, "skipped": n, "median_ms": x, "p95_ms": x,
//                           "metrics": {"<name>": {"mean": x, "median": x, "min": x, "max": x}}}},
//  "total": {"median_ms": x, "p95_ms": x, "fps": x}}
void write_run_json(std::ostream& out, const RunStats& stats, const std::string& graph_name,
                    const std::string& variant);

// A fixed-width table: node, stage, calls, median ms, p95 ms, share of the frame time.
void write_profile_table(std::ostream& out, const RunStats& stats);

}  // namespace facet
