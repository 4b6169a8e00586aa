#pragma once
// template.threshold: a transform stage. It keeps depth up to a limit and marks everything
// farther as "no measurement" (0), the way a grasping pipeline crops the background.

#include <facet/stage.hpp>

namespace facet_template {

class DepthThreshold final : public facet::Stage {
 public:
  static facet::StageSpec spec();
  explicit DepthThreshold(const facet::Params& params);

  void process(facet::ProcessContext& ctx) override;

 private:
  int max_mm_;
};

}  // namespace facet_template
