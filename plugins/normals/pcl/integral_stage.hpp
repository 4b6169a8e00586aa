#pragma once
// normals.integral: PCL's pcl::IntegralImageNormalEstimation wrapped as a stage. PCL types stay
// inside the .cpp; this header exposes only facet types.

#include <memory>

#include "facet/stage.hpp"

namespace facet::normals {

class IntegralStage final : public Stage {
 public:
  static StageSpec spec();
  explicit IntegralStage(const Params& params);
  ~IntegralStage() override;
  void process(ProcessContext& ctx) override;

 private:
  struct Pcl;  // the estimator and its clouds, reused between frames
  std::unique_ptr<Pcl> pcl_;
};

}  // namespace facet::normals
