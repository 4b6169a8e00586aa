#pragma once
// The text reports of `facet compare`: a terminal table, compare.json and compare.csv.

#include <ostream>

#include "facet/framework/compare_summary.hpp"

namespace facet {

// Per variant the frame time (median, p95); then one row per processing stage with each
// variant's median (shared stages marked *), then one row per reported metric with each
// variant's mean, then the best variant by the headline metric. For a sweep, one row per swept
// parameter first, and after the table the best point of each score and the plateau of the
// headline score.
void write_compare_table(std::ostream& out, const CompareSummary& summary);

// {"graph": ..., "frames": n, "warmup": n, "frame_stems": [...],
//  "headline": {"metric": "score.f", "better": "higher", "from_graph": b, "reported": b,
//               "best": variant (when reported)} or null,
//  "variants": [{"name": ..., "median_ms": x, "p95_ms": x, "frame_ms": [...],
//                "stages": [{"node", "merged_id", "stage", "role", "shared", "calls",
//                            "median_ms", "p95_ms"}],
//                "metrics": [{"node", "name", "count", "mean", "median", "min", "max"}]}]}
// For a sweep, each variant also has "sweep": {"node.param": value, ...}, and the top level
// "sweep": {"variant", "params": [...], "best": [...], "plateau": [...]} (docs/compare.md).
void write_compare_json(std::ostream& out, const CompareSummary& summary);

// One row per variant and figure: variant,kind,node,stage,name,shared,count,median,p95,mean
// (kind: total, stage or metric; empty cells where a figure does not apply). For a sweep, one
// more column per swept parameter (named node.param) holds the point's value on every row.
void write_compare_csv(std::ostream& out, const CompareSummary& summary);

}  // namespace facet
