#include "facet/framework/compare_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "facet/framework/json_writer.hpp"
#include "sweep_report.hpp"

namespace facet {
namespace {

// Rows of the table: the (node, name) pairs in first-seen order over all variants.
template <class Item, class Key>
std::vector<std::pair<std::string, std::string>> row_keys(const CompareSummary& summary,
                                                          Item member, Key key) {
  std::vector<std::pair<std::string, std::string>> keys;
  for (const auto& variant : summary.variants) {
    for (const auto& item : variant.*member) {
      auto row = key(item);
      if (row.first.empty()) continue;
      if (std::find(keys.begin(), keys.end(), row) == keys.end()) keys.push_back(row);
    }
  }
  return keys;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string number(double value) {
  return fmt::format("{:.6g}", value);
}

// "best score.f (the headline, higher is better): convex 0.959"; when the graph's headline was
// not reported, that instead.
void write_headline_line(std::ostream& out, const CompareSummary& summary) {
  if (!summary.headline) return;
  const Headline& headline = *summary.headline;
  const auto best = headline.best(summary.variants);
  if (!best) {
    out << fmt::format("\nheadline {}: no variant reported it\n", headline.key());
    return;
  }
  out << fmt::format("\nbest {} (the headline, {} is better): {} {:.4g}\n", headline.key(),
                     goal_name(headline.goal), summary.variants[*best].name,
                     headline.of(summary.variants[*best])->mean);
}

}  // namespace

void write_compare_table(std::ostream& out, const CompareSummary& summary) {
  std::size_t label_width = 24;
  for (const auto& variant : summary.variants) {
    for (const auto& stage : variant.stages)
      label_width = std::max(label_width, stage.node.size() + 2);
    for (const auto& metric : variant.metrics)
      label_width = std::max(label_width, metric.node.size() + metric.name.size() + 3);
  }
  if (summary.sweep) {
    for (const auto& axis : summary.sweep->axes)
      label_width = std::max(label_width, axis.key().size() + 2);
  }
  std::size_t column = 10;
  for (const auto& variant : summary.variants)
    column = std::max(column, variant.name.size() + 1);

  out << fmt::format("{}: {} variant(s), {} frame(s), the first {} left out of the timing\n\n",
                     summary.graph, summary.variants.size(), summary.frames, summary.warmup);
  out << fmt::format("{:<{}}", "", label_width);
  for (const auto& variant : summary.variants)
    out << fmt::format(" {:>{}}", variant.name, column);
  out << '\n';
  const auto print_row = [&](const std::string& label, const auto& cell) {
    out << fmt::format("{:<{}}", label, label_width);
    for (const auto& variant : summary.variants)
      out << fmt::format(" {:>{}}", cell(variant), column);
    out << '\n';
  };
  if (summary.sweep) {
    // The swept values first: the column names repeat them, but a row reads along the sweep.
    const SweepSummary& sweep = *summary.sweep;
    for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
      std::size_t v = 0;
      print_row(sweep.axes[a].key(), [&](const VariantSummary&) {
        const std::size_t point = v++;
        return point < sweep.points.size() ? sweep.axes[a].texts[sweep.points[point].index[a]]
                                           : std::string("-");
      });
    }
  }
  print_row("frame median ms",
            [](const VariantSummary& v) { return fmt::format("{:.2f}", v.median_ms); });
  print_row("frame p95 ms",
            [](const VariantSummary& v) { return fmt::format("{:.2f}", v.p95_ms); });

  out << "\nstage median ms (* = shared, run once for all)\n";
  const auto stages = row_keys(summary, &VariantSummary::stages, [](const StageTiming& s) {
    // By node id alone: a variant may run another stage under the same id.
    return std::make_pair(s.role == NodeRole::process ? s.node : std::string(), std::string());
  });
  for (const auto& [node, unused] : stages) {
    print_row("  " + node, [&, node = node](const VariantSummary& v) {
      for (const auto& s : v.stages) {
        if (s.node == node) return fmt::format("{:.2f}{}", s.median_ms, s.shared ? "*" : " ");
      }
      return std::string("-");
    });
  }

  const auto metrics = row_keys(summary, &VariantSummary::metrics, [](const MetricSummary& m) {
    return std::make_pair(m.node, m.name);
  });
  if (!metrics.empty()) out << "\nmetric mean over frames\n";
  for (const auto& [node, name] : metrics) {
    print_row("  " + node + "." + name, [&, node = node, name = name](const VariantSummary& v) {
      for (const auto& m : v.metrics) {
        if (m.node == node && m.name == name) return fmt::format("{:.4g}", m.mean);
      }
      return std::string("-");
    });
  }
  write_headline_line(out, summary);
  if (summary.sweep) detail::write_sweep_findings(out, *summary.sweep);
}

void write_compare_json(std::ostream& out, const CompareSummary& summary) {
  JsonWriter json(out);
  json.begin_object();
  json.key("graph").value(summary.graph);
  json.key("frames").value(summary.frames);
  json.key("warmup").value(summary.warmup);
  json.key("frame_stems").begin_array();
  for (const auto& stem : summary.frame_stems)
    json.value(stem);
  json.end_array();
  json.key("headline");
  if (summary.headline) {
    const Headline& headline = *summary.headline;
    json.begin_object();
    json.key("metric").value(headline.key());
    json.key("better").value(goal_name(headline.goal));
    json.key("from_graph").value(headline.from_graph);
    json.key("reported").value(headline.reported);
    if (const auto best = headline.best(summary.variants)) {
      json.key("best").value(summary.variants[*best].name);
    }
    json.end_object();
  } else {
    json.null();
  }
  if (summary.sweep) {
    json.key("sweep");
    detail::write_sweep_json(json, *summary.sweep);
  }
  json.key("variants").begin_array();
  for (std::size_t v = 0; v < summary.variants.size(); ++v) {
    const VariantSummary& variant = summary.variants[v];
    json.begin_object();
    json.key("name").value(variant.name);
    if (summary.sweep && v < summary.sweep->points.size()) {
      json.key("sweep");
      detail::write_sweep_point_json(json, *summary.sweep, v);
    }
    json.key("median_ms").value(variant.median_ms);
    json.key("p95_ms").value(variant.p95_ms);
    json.key("frame_ms").begin_array();
    for (const double ms : variant.frame_ms)
      json.value(ms);
    json.end_array();
    json.key("stages").begin_array();
    for (const auto& stage : variant.stages) {
      json.begin_object();
      json.key("node").value(stage.node);
      json.key("merged_id").value(stage.merged_id);
      json.key("stage").value(stage.stage);
      json.key("role").value(role_name(stage.role));
      json.key("shared").value(stage.shared);
      json.key("calls").value(static_cast<std::int64_t>(stage.calls));
      json.key("median_ms").value(stage.median_ms);
      json.key("p95_ms").value(stage.p95_ms);
      json.end_object();
    }
    json.end_array();
    json.key("metrics").begin_array();
    for (const auto& metric : variant.metrics) {
      json.begin_object();
      json.key("node").value(metric.node);
      json.key("name").value(metric.name);
      json.key("count").value(static_cast<std::int64_t>(metric.count));
      json.key("mean").value(metric.mean);
      json.key("median").value(metric.median);
      json.key("min").value(metric.min);
      json.key("max").value(metric.max);
      json.key("frames").begin_array();
      for (const std::int64_t frame : metric.frames)
        json.value(frame);
      json.end_array();
      json.key("values").begin_array();
      for (const double value : metric.values)
        json.value(value);
      json.end_array();
      json.end_object();
    }
    json.end_array();
    json.end_object();
  }
  json.end_array();
  json.end_object();
  out << '\n';
}

void write_compare_csv(std::ostream& out, const CompareSummary& summary) {
  // A sweep's values go in columns after the usual ones, so that readers of the plain layout
  // find every column where it was.
  std::string header = "variant,kind,node,stage,name,shared,count,median,p95,mean";
  if (summary.sweep) {
    for (const auto& axis : summary.sweep->axes) {
      header += ',';
      header += csv_field(axis.key());
    }
  }
  out << header << '\n';
  for (std::size_t v = 0; v < summary.variants.size(); ++v) {
    const VariantSummary& variant = summary.variants[v];
    std::string swept;
    if (summary.sweep) {
      const SweepSummary& sweep = *summary.sweep;
      for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
        swept += ',';
        if (v < sweep.points.size()) swept += sweep.axes[a].texts[sweep.points[v].index[a]];
      }
    }
    const std::string name = csv_field(variant.name);
    out << fmt::format("{},total,,,frame_ms,,{},{},{},{}\n", name, variant.frame_ms.size(),
                       number(variant.median_ms), number(variant.p95_ms), swept);
    for (const auto& stage : variant.stages) {
      out << fmt::format("{},stage,{},{},call_ms,{},{},{},{},{}\n", name, csv_field(stage.node),
                         csv_field(stage.stage), stage.shared ? "yes" : "no", stage.calls,
                         number(stage.median_ms), number(stage.p95_ms), swept);
    }
    for (const auto& metric : variant.metrics) {
      out << fmt::format("{},metric,{},,{},,{},{},,{}{}\n", name, csv_field(metric.node),
                         csv_field(metric.name), metric.count, number(metric.median),
                         number(metric.mean), swept);
    }
  }
}

}  // namespace facet
