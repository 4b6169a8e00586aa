#pragma once
// eval.normal_stability: frame-to-frame angular deviation of the normals in a region of a static
// scene (the paper's Table I), reported as metrics for every frame after the first.

#include <opencv2/core.hpp>

#include "facet/stage.hpp"

namespace facet::eval {

class NormalStabilityEval final : public Stage {
 public:
  static StageSpec spec();
  explicit NormalStabilityEval(const Params& params);

  void process(ProcessContext& ctx) override;

 private:
  // The pixels compared in this frame: the roi, within the largest plane when plane labels are
  // connected. CV_8UC1.
  cv::Mat region_of(ProcessContext& ctx, const cv::Size& size) const;

  cv::Rect roi_;
  cv::Mat previous_normals_;
  cv::Mat previous_region_;
  bool has_previous_ = false;
};

}  // namespace facet::eval
