#pragma once
// eval.stability: frame-to-frame stability of the segments of a static scene (the paper's
// Table II), reported as metrics for every frame after the first (see frame_stability.hpp).

#include <opencv2/core.hpp>

#include "eval/frame_stability.hpp"
#include "facet/stage.hpp"

namespace facet::eval {

class StabilityEval final : public Stage {
 public:
  static StageSpec spec();
  explicit StabilityEval(const Params& params);

  void process(ProcessContext& ctx) override;

 private:
  StabilityOptions options_;
  // The previous frame (packets are immutable, so holding their matrices is enough).
  cv::Mat previous_labels_;
  cv::Mat previous_points_;
  bool has_previous_ = false;
  std::int64_t spurious_total_ = 0;
};

}  // namespace facet::eval
