#pragma once
// What a parameter sweep found: every score (each reported metric's mean and the frame time) at
// every point of the grid, the best point of each, and for the headline score (the graph's
// `headline:`, F by default) the widest range of each swept parameter over which it stays near
// its best — a default chosen there sits on a plateau, not on a peak that the next recording may
// not share.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "facet/framework/score_goal.hpp"
#include "facet/framework/sweep_spec.hpp"

namespace facet {

struct CompareSummary;

struct SweepScore {
  std::string key;     // "score.f" (node.metric), or "frame_ms" for the time per frame
  std::string label;   // as shown: "score.f", "frame median ms"
  std::string metric;  // "f"; empty for the frame time
  ScoreGoal goal = ScoreGoal::higher;
  std::vector<double> values;       // per point (the order of SweepSummary::points); NaN = none
  std::optional<std::size_t> best;  // point index; none for ScoreGoal::none or no value
};

struct SweepPlateau {
  std::string score;     // key of the headline score
  std::size_t axis = 0;  // index into SweepSummary::axes
  double best = 0.0;     // the score's best over the whole grid
  double within = 0.0;   // the tolerance below the best
  double from = 0.0;     // the parameter's range over which the score stays >= best - within
  double to = 0.0;
  std::size_t first = 0;  // the run as point indices (along one line of the grid)
  std::size_t last = 0;
  std::size_t points = 0;
  // For a grid: the other swept parameters' values along that line (node.param -> text).
  std::vector<std::pair<std::string, std::string>> fixed;
};

struct SweepSummary {
  std::string variant;  // the variant the sweep starts from; empty for the graph as written
  std::vector<SweepAxis> axes;
  std::vector<SweepPoint> points;  // in the order of CompareSummary::variants
  std::vector<SweepScore> scores;  // headline scores first, the frame time last
  // Key of the score the plateau is computed for; empty when there is none (no F and no
  // `headline:`). When no point reported it, find_score(headline) is nullptr.
  std::string headline;
  double within = 0.01;
  std::vector<SweepPlateau> plateaus;  // one per axis, when the headline score has values

  const SweepScore* find_score(const std::string& key) const;
};

// `summary` is the comparison of `points` (one variant per point, in that order). The scores are
// the metrics of the eval.* stages (every metric when the graph has none) and the summary's
// headline, which leads them, then the frame time. The plateau is the headline's.
SweepSummary summarize_sweep(const CompareSummary& summary, std::vector<SweepAxis> axes,
                             std::vector<SweepPoint> points, std::string variant, double within);

struct ValueRun {
  std::size_t first = 0;  // indices into the values, inclusive
  std::size_t last = 0;
};

// The widest run of consecutive values >= `threshold`, width measured as x[last] - x[first]
// (x ascending); among runs as wide, the one with more points, then the first. A NaN value
// breaks a run. nullopt when no value reaches the threshold.
std::optional<ValueRun> widest_run_at_least(const std::vector<double>& x,
                                            const std::vector<double>& y, double threshold);

}  // namespace facet
