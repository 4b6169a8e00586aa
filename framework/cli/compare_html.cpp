#include "compare_html.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "facet/framework/svg_plot.hpp"
#include "report_headline.hpp"

namespace facet::cli {
namespace {

constexpr const char* kStyle = R"(body{font-family:sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse;margin:.5em 0 1.5em}
th,td{border:1px solid #ccc;padding:.25em .6em;text-align:right}
th:first-child,td:first-child{text-align:left}
th{background:#f2f2f2}
td.shared{color:#777}
.images td,.images th{text-align:center;vertical-align:top}
.images img{display:block;max-width:320px;image-rendering:pixelated}
.images .score{font-size:90%;color:#444}
.scroll{overflow-x:auto;max-width:100%}
td.changes,th.changes{text-align:left}
td.changes{font-family:monospace;font-size:90%}
p.provenance{color:#555;font-size:90%}
p.headline{font-size:110%}
p.headline.missing{color:#a00}
th.headline,td.headline{background:#fff6d5}
td.best{font-weight:bold}
svg text{font-size:12px}
)";

struct Bar {
  std::string label;
  std::vector<double> values;  // one per variant; negative = none
};

// Grouped horizontal bars: one group per label, one bar per variant.
void write_bar_chart(std::ostream& out, const std::string& title, const std::string& unit,
                     const std::vector<Bar>& bars, const CompareSummary& summary,
                     bool zoom_close_values = false) {
  const std::size_t variants = summary.variants.size();
  double largest = 0.0;
  for (const auto& bar : bars)
    for (const double value : bar.values)
      largest = std::max(largest, value);
  if (bars.empty() || largest <= 0.0) return;
  constexpr int kLabelWidth = 170;
  constexpr int kPlotWidth = 460;
  constexpr int kBarHeight = 12;
  constexpr std::size_t kLegendPerRow = 6;  // 90 px each: any number of variants fits
  const int group_height = static_cast<int>(variants) * kBarHeight + 10;
  const int legend_rows = static_cast<int>((variants + kLegendPerRow - 1) / kLegendPerRow);
  const int legend_height = 18 * std::max(legend_rows, 1);
  // Scores all close together (0.94 .. 0.96) would look equal on an axis from 0: it then starts
  // a little below the smallest, and says so.
  double smallest = largest;
  for (const auto& bar : bars)
    for (const double value : bar.values)
      if (value >= 0.0) smallest = std::min(smallest, value);
  const double axis_from =
      zoom_close_values && smallest > 0.5 * largest
          ? std::max(0.0, std::floor((smallest - 0.1 * (largest - smallest) - 0.01) * 20.0) / 20.0)
          : 0.0;
  const int height = legend_height + static_cast<int>(bars.size()) * group_height + 10;
  out << "<h3>" << xml_escape(title) << "</h3>\n";
  if (axis_from > 0.0) {
    out << fmt::format("<p>The bars start at {:.2f}, not 0: the values are close together.</p>\n",
                       axis_from);
  }
  out << fmt::format(R"(<svg class="chart" xmlns="http://www.w3.org/2000/svg" width="{}" )"
                     R"(height="{}" role="img" aria-label="{}">)",
                     kLabelWidth + kPlotWidth + 80, height, xml_escape(title))
      << '\n';
  for (std::size_t v = 0; v < variants; ++v) {
    const int x = kLabelWidth + static_cast<int>(v % kLegendPerRow) * 90;
    const int y = 2 + 18 * static_cast<int>(v / kLegendPerRow);
    out << fmt::format(R"(<rect x="{}" y="{}" width="10" height="10" fill="{}"/>)"
                       R"(<text x="{}" y="{}">{}</text>)",
                       x, y, series_colour(v), x + 14, y + 9, xml_escape(summary.variants[v].name))
        << '\n';
  }
  for (std::size_t b = 0; b < bars.size(); ++b) {
    const int top = legend_height + static_cast<int>(b) * group_height;
    out << fmt::format(R"(<text x="{}" y="{}" text-anchor="end">{}</text>)", kLabelWidth - 6,
                       top + group_height / 2 + 4, xml_escape(bars[b].label))
        << '\n';
    for (std::size_t v = 0; v < variants && v < bars[b].values.size(); ++v) {
      const double value = bars[b].values[v];
      if (value < 0.0) continue;
      const int y = top + static_cast<int>(v) * kBarHeight;
      const double width = std::max(1.0, kPlotWidth * (value - axis_from) / (largest - axis_from));
      out << fmt::format(R"(<rect x="{}" y="{}" width="{:.1f}" height="{}" fill="{}">)"
                         R"(<title>{}: {:.4g} {}</title></rect>)"
                         R"(<text x="{:.1f}" y="{}">{:.3g}</text>)",
                         kLabelWidth, y, width, kBarHeight - 2, series_colour(v),
                         xml_escape(summary.variants[v].name), value, xml_escape(unit),
                         kLabelWidth + width + 4, y + kBarHeight - 3, value)
          << '\n';
    }
  }
  out << "</svg>\n";
}

// Every timed frame's time, one line per variant: shows drift, outliers and a warm-up too short.
void write_frame_chart(std::ostream& out, const CompareSummary& summary) {
  std::size_t frames = 0;
  double largest = 0.0;
  for (const auto& variant : summary.variants) {
    frames = std::max(frames, variant.frame_ms.size());
    for (const double ms : variant.frame_ms)
      largest = std::max(largest, ms);
  }
  if (frames < 2 || largest <= 0.0) return;
  constexpr int kLeft = 76;
  constexpr int kWidth = 560;
  constexpr int kHeight = 180;
  constexpr int kTop = 24;
  const auto x_of = [&](std::size_t i) {
    return kLeft + kWidth * static_cast<double>(i) / static_cast<double>(frames - 1);
  };
  const auto y_of = [&](double ms) { return kTop + kHeight * (1.0 - ms / largest); };
  out << "<h3>Time of every timed frame</h3>\n";
  out << fmt::format(R"(<svg class="chart" xmlns="http://www.w3.org/2000/svg" width="{}" )"
                     R"(height="{}" role="img" aria-label="frame times">)",
                     kLeft + kWidth + 20, kTop + kHeight + 30)
      << '\n';
  out << fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}" stroke="#999"/>)"
                     R"(<line x1="{0}" y1="{2}" x2="{3}" y2="{2}" stroke="#999"/>)"
                     R"(<text x="{4}" y="{5}" text-anchor="end">{6:.3g} ms</text>)"
                     R"(<text x="{4}" y="{2}" text-anchor="end">0</text>)"
                     R"(<text x="{3}" y="{7}" text-anchor="end">frame {8}</text>)",
                     kLeft, kTop, kTop + kHeight, kLeft + kWidth, kLeft - 4, kTop + 4, largest,
                     kTop + kHeight + 16, summary.warmup + static_cast<std::int64_t>(frames) - 1)
      << '\n';
  for (std::size_t v = 0; v < summary.variants.size(); ++v) {
    const auto& variant = summary.variants[v];
    std::string points;
    for (std::size_t i = 0; i < variant.frame_ms.size(); ++i)
      points += fmt::format("{:.1f},{:.1f} ", x_of(i), y_of(variant.frame_ms[i]));
    out << fmt::format(R"(<polyline fill="none" stroke="{}" stroke-width="1.5" points="{}">)"
                       R"(<title>{}</title></polyline>)",
                       series_colour(v), points, xml_escape(variant.name))
        << '\n';
    out << fmt::format(R"(<rect x="{}" y="4" width="10" height="10" fill="{}"/>)"
                       R"(<text x="{}" y="13">{}</text>)",
                       kLeft + static_cast<int>(v) * 90, series_colour(v),
                       kLeft + static_cast<int>(v) * 90 + 14, xml_escape(variant.name))
        << '\n';
  }
  out << "</svg>\n";
}

std::vector<Bar> stage_bars(const CompareSummary& summary) {
  std::vector<Bar> bars;
  for (std::size_t v = 0; v < summary.variants.size(); ++v) {
    for (const auto& stage : summary.variants[v].stages) {
      if (stage.role != NodeRole::process) continue;
      auto it = std::find_if(bars.begin(), bars.end(),
                             [&](const Bar& bar) { return bar.label == stage.node; });
      if (it == bars.end()) {
        bars.push_back({stage.node, std::vector<double>(summary.variants.size(), -1.0)});
        it = bars.end() - 1;
      }
      it->values[v] = stage.median_ms;
    }
  }
  bars.push_back({"frame (sum)", {}});
  for (const auto& variant : summary.variants)
    bars.back().values.push_back(variant.median_ms);
  return bars;
}

// The scores against ground truth, when some variant reports them (F, P, R and objects with
// F >= 0.75), the headline's first; one axis from 0 to 1 fits them all.
std::vector<Bar> score_bars(const CompareSummary& summary) {
  std::vector<Bar> bars;
  for (const ScoreColumn& column : score_columns(summary)) {
    if (!column.against_truth) continue;
    Bar bar{column.metric, {}};
    for (const auto& variant : summary.variants) {
      const MetricSummary* metric = column.node.empty()
                                        ? variant.find_metric(column.metric)
                                        : variant.find_metric(column.node, column.metric);
      bar.values.push_back(metric != nullptr ? metric->mean : -1.0);
    }
    bars.push_back(std::move(bar));
  }
  return bars;
}

void write_summary_table(std::ostream& out, const CompareSummary& summary,
                         const ReportContext& context) {
  const std::vector<ScoreColumn> scores = score_columns(summary);
  const auto best = summary.headline ? summary.headline->best(summary.variants) : std::nullopt;
  const SweepSummary* sweep = summary.sweep ? &*summary.sweep : nullptr;
  out << "<div class=\"scroll\"><table id=\"summary\"><tr><th>variant</th>";
  if (sweep != nullptr) {
    for (const auto& axis : sweep->axes)
      out << "<th>" << xml_escape(axis.key()) << "</th>";
  }
  for (const ScoreColumn& column : scores)
    out << (column.headline ? "<th class=\"headline\">" : "<th>") << column.html_label << "</th>";
  out << "<th>frame median ms</th><th>frame p95 ms</th><th class=\"changes\">changes</th>";
  out << "</tr>\n";
  for (std::size_t v = 0; v < summary.variants.size(); ++v) {
    const VariantSummary& variant = summary.variants[v];
    out << "<tr><td>" << xml_escape(variant.name) << "</td>";
    if (sweep != nullptr && v < sweep->points.size()) {
      for (std::size_t a = 0; a < sweep->axes.size(); ++a)
        out << "<td>" << xml_escape(sweep->axes[a].texts[sweep->points[v].index[a]]) << "</td>";
    }
    for (const ScoreColumn& column : scores) {
      const MetricSummary* metric = column.node.empty()
                                        ? variant.find_metric(column.metric)
                                        : variant.find_metric(column.node, column.metric);
      // The headline's column stands out, its best value most.
      const char* cell = !column.headline ? "<td>"
                         : best == v      ? "<td class=\"headline best\">"
                                          : "<td class=\"headline\">";
      out << cell << (metric != nullptr ? fmt::format("{:.3f}", metric->mean) : "-") << "</td>";
    }
    out << fmt::format("<td>{:.2f}</td><td>{:.2f}</td>", variant.median_ms, variant.p95_ms);
    const std::string changes =
        v < context.variant_changes.size() ? context.variant_changes[v] : std::string();
    out << "<td class=\"changes\">" << xml_escape(changes) << "</td>";
    out << "</tr>\n";
  }
  out << "</table></div>\n";
}

void write_variant_tables(std::ostream& out, const CompareSummary& summary) {
  for (const auto& variant : summary.variants) {
    out << "<h3>" << xml_escape(variant.name) << "</h3>\n";
    out << "<table class=\"stages\"><tr><th>node</th><th>stage</th><th>role</th><th>shared</th>"
           "<th>calls</th><th>median ms</th><th>p95 ms</th></tr>\n";
    for (const auto& stage : variant.stages) {
      out << fmt::format(
          "<tr><td{}>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.3f}</td>"
          "<td>{:.3f}</td></tr>\n",
          stage.shared ? " class=\"shared\"" : "", xml_escape(stage.merged_id),
          xml_escape(stage.stage), role_name(stage.role), stage.shared ? "yes" : "no", stage.calls,
          stage.median_ms, stage.p95_ms);
    }
    out << "</table>\n";
    if (variant.metrics.empty()) continue;
    out << "<table class=\"metrics\"><tr><th>metric</th><th>frames</th><th>mean</th>"
           "<th>median</th><th>min</th><th>max</th></tr>\n";
    for (const auto& metric : variant.metrics) {
      out << fmt::format(
          "<tr><td>{}.{}</td><td>{}</td><td>{:.4g}</td><td>{:.4g}</td><td>{:.4g}</td>"
          "<td>{:.4g}</td></tr>\n",
          xml_escape(metric.node), xml_escape(metric.name), metric.count, metric.mean,
          metric.median, metric.min, metric.max);
    }
    out << "</table>\n";
  }
}

// The sweep's findings (best point of each score, plateau of F) and its plots.
void write_sweep(std::ostream& out, const SweepSummary& sweep,
                 const std::vector<SweepPlotFile>& plots) {
  out << "<h2>Sweep</h2>\n<table id=\"sweep-best\"><tr><th>score</th><th>best</th><th>at</th>"
         "</tr>\n";
  for (const auto& score : sweep.scores) {
    if (!score.best) continue;
    out << fmt::format("<tr><td>{}</td><td>{:.4g}</td><td>{}</td></tr>\n", xml_escape(score.label),
                       score.values[*score.best], xml_escape(sweep.points[*score.best].name));
  }
  out << "</table>\n";
  for (const auto& plateau : sweep.plateaus) {
    const SweepAxis& axis = sweep.axes[plateau.axis];
    std::string fixed;
    for (const auto& [key, text] : plateau.fixed)
      fixed += fmt::format(", {}={}", key, text);
    out << fmt::format(
        "<p class=\"plateau\">Plateau of {} along {}: {} .. {} ({} point(s){}), where it stays "
        "within {} of its best {:.4g}.</p>\n",
        xml_escape(plateau.score), xml_escape(axis.key()),
        xml_escape(axis.texts[sweep.points[plateau.first].index[plateau.axis]]),
        xml_escape(axis.texts[sweep.points[plateau.last].index[plateau.axis]]), plateau.points,
        xml_escape(fixed), plateau.within, plateau.best);
  }
  for (const auto& plot : plots)
    out << "<h3>" << xml_escape(plot.name) << "</h3>\n" << plot.svg;
}

void write_image_cell(std::ostream& out, const std::string& uri, const std::string& alt,
                      const std::string& caption) {
  if (uri.empty()) {
    out << "<td>-</td>";
    return;
  }
  out << fmt::format(R"(<td><img src="{}" alt="{}">)", uri, xml_escape(alt));
  if (!caption.empty()) out << "<div class=\"score\">" << xml_escape(caption) << "</div>";
  out << "</td>";
}

// Per output folder one table: a row per frame, with its input depth and ground truth when
// found, then each variant's image with that variant's headline value (F) of the frame under it.
void write_images(std::ostream& out, const CompareSummary& summary,
                  const std::vector<ImageRow>& images, bool where_they_disagree) {
  if (images.empty()) return;
  const std::string label = summary.headline ? summary.headline->label() : std::string();
  out << "<h2>Images</h2>\n";
  if (where_they_disagree) {
    out << "<p>The frames whose " << xml_escape(label)
        << " differs most between the variants, largest difference first.</p>\n";
  } else {
    out << "<p>The first frames of the run.</p>\n";
  }
  const bool with_input = std::any_of(images.begin(), images.end(),
                                      [](const ImageRow& row) { return !row.input_uri.empty(); });
  const bool with_truth = std::any_of(images.begin(), images.end(),
                                      [](const ImageRow& row) { return !row.truth_uri.empty(); });
  std::string folder;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const ImageRow& row = images[i];
    if (i == 0 || row.folder != folder) {
      if (i > 0) out << "</table></div>\n";
      folder = row.folder;
      out << "<h3>" << xml_escape(folder)
          << "</h3>\n<div class=\"scroll\"><table class=\"images\"><tr><th>frame</th>";
      if (with_input) out << "<th>input depth</th>";
      if (with_truth) out << "<th>ground truth</th>";
      for (const auto& variant : summary.variants)
        out << "<th>" << xml_escape(variant.name) << "</th>";
      out << "</tr>\n";
    }
    out << "<tr><td>" << xml_escape(row.stem) << "</td>";
    if (with_input) write_image_cell(out, row.input_uri, "input depth " + row.stem, "");
    if (with_truth) write_image_cell(out, row.truth_uri, "ground truth " + row.stem, "");
    for (std::size_t v = 0; v < summary.variants.size(); ++v) {
      const std::string& uri = v < row.data_uris.size() ? row.data_uris[v] : std::string();
      const auto value = frame_headline(summary, v, row.stem);
      write_image_cell(out, uri, summary.variants[v].name + " " + row.folder + " " + row.stem,
                       value ? fmt::format("{} {:.3f}", label, *value) : "");
    }
    out << "</tr>\n";
  }
  out << "</table></div>\n";
}

}  // namespace

void write_compare_html(std::ostream& out, const CompareSummary& summary,
                        const std::vector<ImageRow>& images, const ReportContext& context,
                        const std::vector<SweepPlotFile>& plots) {
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>facet compare: "
      << xml_escape(summary.graph) << "</title>\n<style>" << kStyle << "</style></head>\n<body>\n";
  out << "<h1>facet compare: " << xml_escape(summary.graph) << "</h1>\n";
  out << fmt::format(
      "<p>{} variant(s) in one merged graph, {} frame(s); the first {} are warm-up and left out "
      "of every time. A frame's time is the sum of the processing stages a variant runs, its own "
      "and the shared ones (sources and sinks not counted); shared stages ran once per frame for "
      "all variants.</p>\n",
      summary.variants.size(), summary.frames, summary.warmup);
  out << "<p class=\"provenance\">facet " << xml_escape(context.facet_version) << ", "
      << xml_escape(context.date_utc);
  if (!context.input.empty()) out << "; input " << xml_escape(context.input);
  out << "<br><code>" << xml_escape(context.command_line) << "</code></p>\n";
  out << "<h2>Summary</h2>\n";
  write_headline_html(out, summary);
  write_summary_table(out, summary, context);
  if (summary.sweep) write_sweep(out, *summary.sweep, plots);
  write_images(out, summary, images, context.images_where_they_disagree);
  out << "<h2>Plots</h2>\n";
  write_bar_chart(out, "Scores against ground truth (mean over frames)", "", score_bars(summary),
                  summary, /*zoom_close_values=*/true);
  write_bar_chart(out, "Stage median time per frame", "ms", stage_bars(summary), summary);
  write_frame_chart(out, summary);
  out << "<h2>Per variant</h2>\n";
  write_variant_tables(out, summary);
  // Counts the images that decoded and the sweep lines the browser laid out (as SVG, with a
  // size), for a check in a headless browser; the page needs no script.
  out << "<script>window.addEventListener('load',function(){var n=0;"
         "document.querySelectorAll('img').forEach(function(i){if(i.naturalWidth>0)n++;});"
         "document.body.setAttribute('data-images-loaded',String(n));var s=0;"
         "document.querySelectorAll('svg.sweep polyline.line').forEach(function(l){"
         "if(l.getBBox&&l.getBBox().width>0)s++;});"
         "document.body.setAttribute('data-sweep-lines',String(s));});</script>\n";
  out << "</body></html>\n";
}

}  // namespace facet::cli
