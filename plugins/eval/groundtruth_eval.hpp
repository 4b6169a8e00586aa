#pragma once
// eval.groundtruth: scores predicted segment ids against ground-truth labels, frame by frame,
// and reports the scores as metrics (see overlap_scores.hpp for the measures).

#include "eval/overlap_scores.hpp"
#include "facet/stage.hpp"

namespace facet::eval {

class GroundTruthEval final : public Stage {
 public:
  static StageSpec spec();
  explicit GroundTruthEval(const Params& params);

  void process(ProcessContext& ctx) override;

 private:
  OverlapOptions options_;
};

// "1, 4" -> {1, 4}; throws StageError naming the parameter on anything but integers.
std::set<std::int32_t> parse_label_list(const std::string& text, const char* param);

}  // namespace facet::eval
