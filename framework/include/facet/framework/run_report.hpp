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
//  "total": {"median_ms": x, "p95_ms": x, "fps": x, "throughput_fps": x, "wall_ms": x,
//            "dropped": n},
//  "per_frame": [{"frame": i, "stem": s, "ms": x, "stages_ms": {"<node id>": x},
//                 "metrics": {"<node id>.<name>": x}}]}
// total.median_ms and p95_ms are the per-frame latency; fps is 1000 / median_ms (what one frame
// at a time would achieve), throughput_fps is frames / wall time (what the run achieved, with
// several frames in flight more than fps); dropped counts frames a `latest` source replaced.
void write_run_json(std::ostream& out, const RunStats& stats, const std::string& graph_name,
                    const std::string& variant);

// A fixed-width table: node, stage, calls, median ms, p95 ms, share of the frame time; then the
// throughput.
void write_profile_table(std::ostream& out, const RunStats& stats);

}  // namespace facet
