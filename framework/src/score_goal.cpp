#include "facet/framework/score_goal.hpp"

namespace facet {

ScoreGoal goal_of_metric(const std::string& metric_name) {
  for (const char* lower : {"over_segmented", "under_segmented", "merged_objects"}) {
    if (metric_name == lower) return ScoreGoal::lower;
  }
  if (metric_name.ends_with("_ms")) return ScoreGoal::lower;
  for (const char* none : {"truth_objects", "segments", "scored"}) {
    if (metric_name == none) return ScoreGoal::none;
  }
  return ScoreGoal::higher;
}

const char* goal_name(ScoreGoal goal) {
  switch (goal) {
    case ScoreGoal::higher:
      return "higher";
    case ScoreGoal::lower:
      return "lower";
    case ScoreGoal::none:
      break;
  }
  return "none";
}

}  // namespace facet
