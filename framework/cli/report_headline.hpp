#pragma once
// The comparison report's lead: the best variant by the headline metric (the graph's
// `headline:`, F by default), the score columns of the summary table with the headline's first,
// and what to say when the graph's headline was not reported.

#include <ostream>
#include <string>
#include <vector>

#include "facet/framework/compare_summary.hpp"

namespace facet::cli {

// A score column of the summary table: a metric of one node, or of the first node that reports
// it when `node` is empty.
struct ScoreColumn {
  std::string html_label;  // "F", "objects F&ge;0.75", ...
  std::string node;
  std::string metric;
  bool headline = false;       // the headline metric's column
  bool against_truth = false;  // one of the ground-truth scores (F, P, R, objects), in [0, 1]
};

// The headline metric's column first when some variant reported it, then those of F,
// precision, recall and objects segmented that some variant reported (the headline not twice).
std::vector<ScoreColumn> score_columns(const CompareSummary& summary);

// Why no variant reported the graph's headline metric: what its node reported instead (with the
// closest name), or that the node reported nothing, or did not run.
std::string why_headline_is_missing(const CompareSummary& summary);

// <p class="headline">: the best variant by the headline metric and every other's value; or,
// when the graph named a headline that no variant reported, a paragraph that says so. Nothing
// when there is no headline.
void write_headline_html(std::ostream& out, const CompareSummary& summary);

}  // namespace facet::cli
