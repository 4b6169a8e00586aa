#include "report_headline.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "facet/framework/diagnostics.hpp"
#include "facet/framework/svg_plot.hpp"

namespace facet::cli {
namespace {

// eval.groundtruth's scores as the summary table shows them, in this order.
const std::vector<std::pair<std::string, std::string>> kTruthScores = {
    {"F", "f"},
    {"precision", "precision"},
    {"recall", "recall"},
    {"objects F&ge;0.75", "objects_f75_ratio"}};

}  // namespace

std::vector<ScoreColumn> score_columns(const CompareSummary& summary) {
  std::vector<ScoreColumn> columns;
  const Headline* headline =
      summary.headline && summary.headline->reported ? &*summary.headline : nullptr;
  if (headline != nullptr) {
    ScoreColumn column{xml_escape(headline->label()), headline->node, headline->metric, true,
                       false};
    for (const auto& score : kTruthScores) {
      if (score.second != headline->metric) continue;
      column.html_label = score.first;
      column.against_truth = true;
    }
    columns.push_back(std::move(column));
  }
  for (const auto& score : kTruthScores) {
    const std::string& metric = score.second;
    if (headline != nullptr && headline->metric == metric) continue;
    const bool reported = std::any_of(
        summary.variants.begin(), summary.variants.end(),
        [&metric](const VariantSummary& v) { return v.find_metric(metric) != nullptr; });
    if (reported) columns.push_back({score.first, "", metric, false, true});
  }
  return columns;
}

std::string why_headline_is_missing(const CompareSummary& summary) {
  if (!summary.headline) return {};
  const std::string& node = summary.headline->node;
  bool ran = false;
  std::vector<std::string> reported;
  for (const auto& variant : summary.variants) {
    ran = ran || std::any_of(variant.stages.begin(), variant.stages.end(),
                             [&node](const StageTiming& stage) { return stage.node == node; });
    for (const auto& metric : variant.metrics) {
      if (metric.node == node &&
          std::find(reported.begin(), reported.end(), metric.name) == reported.end()) {
        reported.push_back(metric.name);
      }
    }
  }
  if (!reported.empty()) {
    std::string text = "node '" + node + "' reported ";
    for (std::size_t i = 0; i < reported.size(); ++i)
      text += (i > 0 ? ", " : "") + reported[i];
    const std::string guess = did_you_mean(summary.headline->metric, reported);
    return guess.empty() ? text : text + "; did you mean '" + node + "." + guess + "'?";
  }
  if (ran) return "node '" + node + "' reported no metric";
  return "node '" + node + "' did not run (is it left out by a 'when:'?)";
}

void write_headline_html(std::ostream& out, const CompareSummary& summary) {
  if (!summary.headline) return;
  const Headline& headline = *summary.headline;
  const auto best = headline.best(summary.variants);
  if (!best) {
    out << fmt::format(
        "<p class=\"headline missing\">The graph's headline metric <b>{}</b> was reported by no "
        "variant: {}. No variant is named best.</p>\n",
        xml_escape(headline.key()), xml_escape(why_headline_is_missing(summary)));
    return;
  }
  out << fmt::format(
      "<p class=\"headline\">Best {} ({}mean over frames{}): <b>{}</b> {:.3f}",
      xml_escape(headline.label()), headline.from_graph ? xml_escape(headline.key()) + ", " : "",
      headline.goal == ScoreGoal::lower ? ", lower is better" : "",
      xml_escape(summary.variants[*best].name), headline.of(summary.variants[*best])->mean);
  for (std::size_t v = 0; v < summary.variants.size(); ++v) {
    const MetricSummary* value = headline.of(summary.variants[v]);
    if (v == *best || value == nullptr) continue;
    out << fmt::format("; {} {:.3f}", xml_escape(summary.variants[v].name), value->mean);
  }
  out << "</p>\n";
}

}  // namespace facet::cli
