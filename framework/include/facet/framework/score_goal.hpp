#pragma once
// Which way a reported metric is better: what a sweep's "best point" and a graph's headline
// metric (the `headline:` key of a graph file) go by.

#include <string>

namespace facet {

// Times and the over-/under-segmentation counts are better low; counts that describe the scene
// rather than the result (truth objects, segments, scored frames) have no best; every other
// metric is taken as better high.
enum class ScoreGoal { higher, lower, none };

// By the metric's name: those of eval.groundtruth as above, and a name ending in `_ms` (a time,
// by the project's rule of units in names) is better low.
ScoreGoal goal_of_metric(const std::string& metric_name);

// "higher", "lower" or "none", as compare.json and graph files write it.
const char* goal_name(ScoreGoal goal);

}  // namespace facet
