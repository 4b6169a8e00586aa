// The eval plugin: stages that score a graph's results against ground truth or over time.
#include "facet/plugin.hpp"

#include "eval/groundtruth_eval.hpp"
#include "eval/normal_stability_eval.hpp"
#include "eval/stability_eval.hpp"

FACET_PLUGIN("facet_eval", "0.1.0") {
  registrar.add<facet::eval::GroundTruthEval>();
  registrar.add<facet::eval::StabilityEval>();
  registrar.add<facet::eval::NormalStabilityEval>();
}
