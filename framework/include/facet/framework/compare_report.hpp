#pragma once
// The text reports of `facet compare`: a terminal table, compare.json and compare.csv.

#include <ostream>

#include "facet/framework/compare_summary.hpp"

namespace facet {

// Per variant the frame time (median, p95); then one row per processing stage with each
// variant's median (shared stages marked *), then one row per reported metric with each
// variant's mean.
void write_compare_table(std::ostream& out, const CompareSummary& summary);

// {"graph": ..., "frames": n, "warmup": n,
//  "variants": [{"name": ..., "median_ms": x, "p95_ms": x, "frame_ms": [...],
//                "stages": [{"node", "merged_id", "stage", "role", "shared", "calls",
//                            "median_ms", "p95_ms"}],
//                "metrics": [{"node", "name", "count", "mean", "median", "min", "max"}]}]}
void write_compare_json(std::ostream& out, const CompareSummary& summary);

// One row per variant and figure: variant,kind,node,stage,name,shared,count,median,p95,mean
// (kind: total, stage or metric; empty cells where a figure does not apply).
void write_compare_csv(std::ostream& out, const CompareSummary& summary);

}  // namespace facet
