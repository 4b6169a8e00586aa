#pragma once
// convert.points: the organized point cloud of a depth image.

#include "convert/back_projection.hpp"
#include "facet/stage.hpp"

namespace facet::convert {

class PointsStage final : public Stage {
 public:
  static StageSpec spec();
  explicit PointsStage(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  DepthRange range_;
};

}  // namespace facet::convert
