#include "facet/framework/sweep_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "facet/framework/compare_summary.hpp"

namespace facet {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
// Stages whose metrics are scores: eval.groundtruth, eval.stability, ...
constexpr const char* kEvalFamily = "eval.";
// F values such as 0.97 and 0.96 differ by a hair less than 0.01 in binary: such a pair counts
// as within the tolerance, as it does in decimal.
constexpr double kTolerance = 1e-9;

// The graph's headline leads the list (and the plots), then the scores the team reads first, in
// this order.
int headline_rank(const SweepScore& score, const std::string& headline_key) {
  static constexpr const char* kFirst[] = {"f", "precision", "recall", "objects_f75_ratio",
                                           "mean_iou"};
  if (score.key == headline_key) return -1;
  for (int i = 0; i < static_cast<int>(std::size(kFirst)); ++i) {
    if (score.metric == kFirst[i]) return i;
  }
  return static_cast<int>(std::size(kFirst));
}

std::optional<std::size_t> best_of(const std::vector<double>& values, ScoreGoal goal) {
  if (goal == ScoreGoal::none) return std::nullopt;
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isnan(values[i])) continue;
    // Strictly better only: ties go to the first point, the lowest parameter value.
    const bool better = !best || (goal == ScoreGoal::higher ? values[i] > values[*best]
                                                            : values[i] < values[*best]);
    if (better) best = i;
  }
  return best;
}

// The widest plateau of `score` along axis `axis`: over every line of the grid (the other axes
// fixed), the widest run of points within `within` of the score's best over the whole grid (above
// it for a score that is better low).
std::optional<SweepPlateau> plateau_along(const SweepSummary& sweep, const SweepScore& score,
                                          std::size_t axis) {
  if (!score.best) return std::nullopt;
  const double best = score.values[*score.best];
  // A score better low is searched as its negative: the run then is of values >= -(best + within).
  const double sign = score.goal == ScoreGoal::lower ? -1.0 : 1.0;
  // Lines: points that agree on every other axis, ordered along `axis`.
  std::map<std::vector<std::size_t>, std::vector<std::size_t>> lines;
  for (std::size_t p = 0; p < sweep.points.size(); ++p) {
    auto others = sweep.points[p].index;
    others.erase(others.begin() + static_cast<std::ptrdiff_t>(axis));
    lines[others].push_back(p);
  }
  std::optional<SweepPlateau> widest;
  for (auto& [others, line] : lines) {
    std::sort(line.begin(), line.end(), [&](std::size_t a, std::size_t b) {
      return sweep.points[a].index[axis] < sweep.points[b].index[axis];
    });
    std::vector<double> x;
    std::vector<double> y;
    for (const std::size_t p : line) {
      x.push_back(sweep.axes[axis].values[sweep.points[p].index[axis]]);
      y.push_back(sign * score.values[p]);
    }
    const auto run = widest_run_at_least(x, y, sign * best - sweep.within - kTolerance);
    if (!run) continue;
    const double width = x[run->last] - x[run->first];
    const std::size_t points = run->last - run->first + 1;
    if (widest && (width < widest->to - widest->from ||
                   (width == widest->to - widest->from && points <= widest->points))) {
      continue;
    }
    SweepPlateau plateau;
    plateau.score = score.key;
    plateau.axis = axis;
    plateau.best = best;
    plateau.within = sweep.within;
    plateau.from = x[run->first];
    plateau.to = x[run->last];
    plateau.first = line[run->first];
    plateau.last = line[run->last];
    plateau.points = points;
    for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
      if (a == axis) continue;
      plateau.fixed.emplace_back(sweep.axes[a].key(),
                                 sweep.axes[a].texts[sweep.points[line.front()].index[a]]);
    }
    widest = std::move(plateau);
  }
  return widest;
}

}  // namespace

const SweepScore* SweepSummary::find_score(const std::string& key) const {
  const auto it =
      std::find_if(scores.begin(), scores.end(), [&](const SweepScore& s) { return s.key == key; });
  return it == scores.end() ? nullptr : &*it;
}

std::optional<ValueRun> widest_run_at_least(const std::vector<double>& x,
                                            const std::vector<double>& y, double threshold) {
  std::optional<ValueRun> widest;
  const std::size_t n = std::min(x.size(), y.size());
  for (std::size_t i = 0; i < n;) {
    if (std::isnan(y[i]) || y[i] < threshold) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < n && !std::isnan(y[j + 1]) && y[j + 1] >= threshold)
      ++j;
    const auto wider = [&](const ValueRun& run) {
      const double width = x[j] - x[i];
      const double run_width = x[run.last] - x[run.first];
      return width > run_width || (width == run_width && j - i > run.last - run.first);
    };
    if (!widest || wider(*widest)) widest = ValueRun{i, j};
    i = j + 1;
  }
  return widest;
}

SweepSummary summarize_sweep(const CompareSummary& summary, std::vector<SweepAxis> axes,
                             std::vector<SweepPoint> points, std::string variant, double within) {
  SweepSummary sweep;
  sweep.variant = std::move(variant);
  sweep.axes = std::move(axes);
  sweep.points = std::move(points);
  sweep.within = within;
  const std::size_t count = std::min(sweep.points.size(), summary.variants.size());

  // The graph's headline (docs/graph-format.md), else the first node's F, as
  // CompareSummary::headline takes it.
  const std::string headline_key = summary.headline ? summary.headline->key() : std::string();
  // The scores are what the eval stages report, and the headline; the other stages' metrics
  // (valid pixels, patch counts, ...) describe the work, not its quality. A graph without an eval
  // stage has only those, so then they are all plotted.
  std::set<std::string> eval_nodes;
  for (std::size_t p = 0; p < count; ++p) {
    for (const auto& stage : summary.variants[p].stages) {
      if (stage.stage.starts_with(kEvalFamily)) eval_nodes.insert(stage.node);
    }
  }
  // Every such metric any point reported, first seen first; the mean over frames at each point.
  for (std::size_t p = 0; p < count; ++p) {
    for (const auto& metric : summary.variants[p].metrics) {
      const std::string key = metric.node + "." + metric.name;
      if (!eval_nodes.empty() && eval_nodes.count(metric.node) == 0 && key != headline_key) {
        continue;
      }
      if (sweep.find_score(key) != nullptr) continue;
      const ScoreGoal goal =
          key == headline_key ? summary.headline->goal : goal_of_metric(metric.name);
      SweepScore score{key, key, metric.name, goal, {}, {}};
      for (std::size_t q = 0; q < sweep.points.size(); ++q) {
        double value = kNone;
        if (q < count) {
          for (const auto& m : summary.variants[q].metrics) {
            if (m.node == metric.node && m.name == metric.name) value = m.mean;
          }
        }
        score.values.push_back(value);
      }
      sweep.scores.push_back(std::move(score));
    }
  }
  std::stable_sort(sweep.scores.begin(), sweep.scores.end(),
                   [&](const SweepScore& a, const SweepScore& b) {
                     return headline_rank(a, headline_key) < headline_rank(b, headline_key);
                   });
  SweepScore time{"frame_ms", "frame median ms", "", ScoreGoal::lower, {}, {}};
  for (std::size_t q = 0; q < sweep.points.size(); ++q)
    time.values.push_back(q < count ? summary.variants[q].median_ms : kNone);
  sweep.scores.push_back(std::move(time));
  for (auto& score : sweep.scores)
    score.best = best_of(score.values, score.goal);

  // Without a CompareSummary::headline (a summary made by hand), the first node's F.
  const auto headline =
      std::find_if(sweep.scores.begin(), sweep.scores.end(), [&](const SweepScore& s) {
        return summary.headline ? s.key == headline_key : s.metric == kDefaultHeadlineMetric;
      });
  sweep.headline = headline_key;
  if (headline != sweep.scores.end()) {
    sweep.headline = headline->key;
    for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
      if (auto plateau = plateau_along(sweep, *headline, a)) sweep.plateaus.push_back(*plateau);
    }
  }
  return sweep;
}

}  // namespace facet
