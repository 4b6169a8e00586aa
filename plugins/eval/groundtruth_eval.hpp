#pragma once
// eval.groundtruth: scores predicted segment ids against ground-truth labels, frame by frame,
// and reports the scores as metrics (see overlap_scores.hpp for the measures).

#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <variant>

#include "eval/overlap_scores.hpp"
#include "facet/contract.hpp"
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

// A set of positive label ids, written "1, 4" (empty = none): eval.groundtruth's
// truth_background.
struct LabelIds {
  std::set<std::int32_t> ids;
};

}  // namespace facet::eval

template <>
struct facet::ParamTraits<facet::eval::LabelIds> {
  static std::variant<facet::eval::LabelIds, std::string> parse(std::string_view text);
  static std::string format(const facet::eval::LabelIds& value);
};
