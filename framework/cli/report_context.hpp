#pragma once
// What the comparison report says besides the figures: where they came from (facet version,
// command line, input, date), what each variant changes, and which frames to show.

#include <optional>
#include <string>
#include <vector>

#include "facet/framework/compare_summary.hpp"
#include "facet/framework/graph_spec.hpp"

namespace facet::cli {

struct ReportContext {
  std::string facet_version;
  std::string command_line;
  std::string input;                         // the graph's `input` parameter, when it has one
  std::string date_utc;                      // "2026-12-03 17:58 UTC"
  std::vector<std::string> variant_changes;  // per variant: "normals: normals.pca window=5"
  bool images_where_they_disagree = false;   // the images are of those frames, not the first
};

// What `variant` changes against the graph as written, node by node: a new stage with its
// params ("normals: normals.pca window=5"), changed params ("edges.threshold=0.9"), added and
// removed nodes; "the graph as written" when nothing.
std::string describe_changes(const GraphSpec& written, const GraphSpec& variant);

// The stems of the frames whose headline metric (F by default) differs most between the variants
// (largest spread first), when they report it and there are several; otherwise the first frames
// run. At most `count`.
std::vector<std::string> frames_to_show(const CompareSummary& summary, std::size_t count,
                                        bool where_they_disagree);

// The headline metric's value that variant `v` reported for the frame with this stem, if any.
std::optional<double> frame_headline(const CompareSummary& summary, std::size_t v,
                                     const std::string& stem);

// "2026-12-03 17:58 UTC", now.
std::string utc_now_text();

}  // namespace facet::cli
