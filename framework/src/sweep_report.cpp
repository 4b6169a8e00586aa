#include "sweep_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "facet/framework/compare_summary.hpp"

namespace facet::detail {
namespace {

void write_axis_value(JsonWriter& json, const SweepAxis& axis, std::size_t index) {
  const double value = axis.values[index];
  if (axis.integral) {
    json.value(static_cast<std::int64_t>(std::llround(value)));
  } else {
    json.value(value);
  }
}

void write_number(JsonWriter& json, const SweepAxis& axis, double value) {
  if (axis.integral) {
    json.value(static_cast<std::int64_t>(std::llround(value)));
  } else {
    json.value(value);
  }
}

std::string range_text(const SweepSummary& sweep, const SweepPlateau& plateau) {
  const SweepAxis& axis = sweep.axes[plateau.axis];
  std::string text = fmt::format("{} {} .. {} ({} point{})", axis.key(),
                                 axis.texts[sweep.points[plateau.first].index[plateau.axis]],
                                 axis.texts[sweep.points[plateau.last].index[plateau.axis]],
                                 plateau.points, plateau.points == 1 ? "" : "s");
  if (!plateau.fixed.empty()) {
    text += " at ";
    for (std::size_t i = 0; i < plateau.fixed.size(); ++i)
      text += (i > 0 ? "," : "") + plateau.fixed[i].first + "=" + plateau.fixed[i].second;
  }
  return text;
}

}  // namespace

void write_sweep_findings(std::ostream& out, const SweepSummary& sweep) {
  out << "\nsweep";
  if (!sweep.variant.empty()) out << " on variant " << sweep.variant;
  out << fmt::format(" ({} point{}):\n", sweep.points.size(), sweep.points.size() == 1 ? "" : "s");
  for (const auto& axis : sweep.axes) {
    out << fmt::format("  {} {} .. {} step {} ({} values)\n", axis.key(), axis.texts.front(),
                       axis.texts.back(), fmt::format("{:.{}f}", axis.step, axis.decimals),
                       axis.values.size());
  }
  std::size_t width = 24;
  for (const auto& score : sweep.scores)
    width = std::max(width, score.label.size() + 4);
  out << "\nbest point of each score\n";
  for (const auto& score : sweep.scores) {
    if (!score.best) continue;
    out << fmt::format("  {:<{}} {:>10.4g}  {}{}\n", score.label, width - 2,
                       score.values[*score.best], sweep.points[*score.best].name,
                       score.goal == ScoreGoal::lower ? "  (lower is better)" : "");
  }
  if (sweep.headline.empty()) {
    out << "\nno plateau: no stage reports the metric '" << kDefaultHeadlineMetric << "'\n";
    return;
  }
  if (sweep.find_score(sweep.headline) == nullptr) {
    out << "\nno plateau: no point reported the headline metric '" << sweep.headline << "'\n";
    return;
  }
  for (const auto& plateau : sweep.plateaus) {
    out << fmt::format("\nplateau of {} (within {} of its best {:.4g}): {}\n", plateau.score,
                       plateau.within, plateau.best, range_text(sweep, plateau));
    // A plateau cut by the end of the range may go on beyond it: the sweep cannot tell.
    const SweepAxis& axis = sweep.axes[plateau.axis];
    const bool at_start = sweep.points[plateau.first].index[plateau.axis] == 0;
    const bool at_stop = sweep.points[plateau.last].index[plateau.axis] + 1 == axis.values.size();
    if (at_start || at_stop) {
      out << fmt::format("  it reaches the {} of the sweep and may extend beyond it\n",
                         at_start && at_stop ? "start and the stop"
                         : at_start          ? "start"
                                             : "stop");
    }
  }
}

void write_sweep_point_json(JsonWriter& json, const SweepSummary& sweep, std::size_t point) {
  json.begin_object();
  for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
    json.key(sweep.axes[a].key());
    write_axis_value(json, sweep.axes[a], sweep.points[point].index[a]);
  }
  json.end_object();
}

void write_sweep_json(JsonWriter& json, const SweepSummary& sweep) {
  json.begin_object();
  json.key("variant").value(sweep.variant);
  json.key("params").begin_array();
  for (const auto& axis : sweep.axes) {
    json.begin_object();
    json.key("name").value(axis.key());
    // A graph parameter belongs to no node.
    json.key("node");
    if (axis.is_graph_param()) {
      json.null();
    } else {
      json.value(axis.node);
    }
    json.key("param").value(axis.param);
    json.key("start");
    write_number(json, axis, axis.start);
    json.key("stop");
    write_number(json, axis, axis.stop);
    json.key("step");
    write_number(json, axis, axis.step);
    json.key("values").begin_array();
    for (std::size_t i = 0; i < axis.values.size(); ++i)
      write_axis_value(json, axis, i);
    json.end_array();
    json.end_object();
  }
  json.end_array();
  json.key("headline").value(sweep.headline);
  json.key("within").value(sweep.within);
  json.key("best").begin_array();
  for (const auto& score : sweep.scores) {
    if (!score.best) continue;
    json.begin_object();
    json.key("score").value(score.key);
    json.key("goal").value(goal_name(score.goal));
    json.key("value").value(score.values[*score.best]);
    json.key("variant").value(sweep.points[*score.best].name);
    json.key("at");
    write_sweep_point_json(json, sweep, *score.best);
    json.end_object();
  }
  json.end_array();
  json.key("plateau").begin_array();
  for (const auto& plateau : sweep.plateaus) {
    const SweepAxis& axis = sweep.axes[plateau.axis];
    json.begin_object();
    json.key("param").value(axis.key());
    json.key("score").value(plateau.score);
    json.key("best").value(plateau.best);
    json.key("within").value(plateau.within);
    json.key("from");
    write_number(json, axis, plateau.from);
    json.key("to");
    write_number(json, axis, plateau.to);
    json.key("points").value(static_cast<std::int64_t>(plateau.points));
    json.key("first").value(sweep.points[plateau.first].name);
    json.key("last").value(sweep.points[plateau.last].name);
    json.key("fixed").begin_object();
    for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
      if (a == plateau.axis) continue;
      json.key(sweep.axes[a].key());
      write_axis_value(json, sweep.axes[a], sweep.points[plateau.first].index[a]);
    }
    json.end_object();
    json.end_object();
  }
  json.end_array();
  json.end_object();
}

}  // namespace facet::detail
