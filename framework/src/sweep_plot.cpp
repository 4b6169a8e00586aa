#include "facet/framework/sweep_plot.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>

namespace facet {

std::string sweep_plot_file_name(const SweepAxis& axis) {
  return "sweep_" + axis.key() + ".svg";
}

LinePlot sweep_plot(const SweepSummary& sweep, std::size_t axis) {
  const SweepAxis& swept = sweep.axes.at(axis);
  LinePlot plot;
  plot.title = "Sweep of " + swept.key() +
               (sweep.variant.empty() ? std::string() : " (variant " + sweep.variant + ")");
  plot.x_label = swept.key();
  plot.x = swept.values;

  // Lines: the points that agree on every other axis, by those axes' indices.
  std::map<std::vector<std::size_t>, std::size_t> line_of;
  std::vector<std::string> labels;
  std::vector<std::size_t> point_line(sweep.points.size());
  for (std::size_t p = 0; p < sweep.points.size(); ++p) {
    auto others = sweep.points[p].index;
    others.erase(others.begin() + static_cast<std::ptrdiff_t>(axis));
    const auto [it, added] = line_of.try_emplace(others, labels.size());
    if (added) {
      std::string label;
      for (std::size_t a = 0, o = 0; a < sweep.axes.size(); ++a) {
        if (a == axis) continue;
        if (!label.empty()) label += ',';
        label += sweep.axes[a].key() + "=" + sweep.axes[a].texts[others[o++]];
      }
      labels.push_back(label.empty() ? "mean over frames (time: median)" : label);
    }
    point_line[p] = it->second;
  }
  // Lines in the order of the other axes' values, not of first appearance.
  std::vector<std::size_t> order(labels.size());
  {
    std::size_t rank = 0;
    for (const auto& [others, line] : line_of)
      order[line] = rank++;
  }

  const SweepPlateau* plateau = nullptr;
  for (const auto& candidate : sweep.plateaus) {
    if (candidate.axis == axis) plateau = &candidate;
  }
  for (const auto& score : sweep.scores) {
    PlotPanel panel;
    panel.title = score.label;
    panel.lines.resize(labels.size());
    for (std::size_t l = 0; l < labels.size(); ++l) {
      panel.lines[order[l]].label = labels[l];
      panel.lines[order[l]].y.assign(plot.x.size(), std::numeric_limits<double>::quiet_NaN());
    }
    for (std::size_t p = 0; p < sweep.points.size() && p < score.values.size(); ++p)
      panel.lines[order[point_line[p]]].y[sweep.points[p].index[axis]] = score.values[p];
    if (score.best) {
      const SweepPoint& best = sweep.points[*score.best];
      panel.best = PlotMark{order[point_line[*score.best]], best.index[axis],
                            fmt::format("best {:.4g} at {}", score.values[*score.best], best.name)};
    }
    if (plateau != nullptr && score.key == plateau->score) {
      std::string where = fmt::format("{} {} .. {}", swept.key(),
                                      swept.texts[sweep.points[plateau->first].index[axis]],
                                      swept.texts[sweep.points[plateau->last].index[axis]]);
      for (const auto& [key, text] : plateau->fixed)
        where += fmt::format(", {}={}", key, text);
      panel.band = PlotBand{plateau->from, plateau->to,
                            fmt::format("plateau: {} within {} of its best {:.4g}: {}", score.label,
                                        plateau->within, plateau->best, where)};
      plot.band_legend =
          fmt::format("plateau: {} within {} of its best", score.label, plateau->within);
    }
    plot.panels.push_back(std::move(panel));
  }
  return plot;
}

}  // namespace facet
