#pragma once
// shape.pca_box: per object, the oriented box from PCA of its visible points — the simple model
// the paper compared superquadrics against (it is always shifted towards the camera).

#include "facet/stage.hpp"
#include "shape/grasp_rule.hpp"

namespace facet::shape {

class PcaBoxStage final : public Stage {
 public:
  static StageSpec spec();
  explicit PcaBoxStage(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  double support_tolerance_m_;
  double support_max_gap_m_;
  GraspRule grasp_rule_;
};

}  // namespace facet::shape
