// The eval plugin: stages that score a graph's results against ground truth.
#include "facet/plugin.hpp"

#include "eval/groundtruth_eval.hpp"

FACET_PLUGIN("facet_eval", "0.1.0") {
  registrar.add<facet::eval::GroundTruthEval>();
}
