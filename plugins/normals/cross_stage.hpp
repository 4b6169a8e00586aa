#pragma once
// normals.cross: the paper's surface normals, from the cross product of neighbours at radius r.

#include <opencv2/core/mat.hpp>

#include "facet/stage.hpp"
#include "normals/cross_kernel.hpp"
#include "normals/depth_space.hpp"
#include "normals/normal_smoothing.hpp"

namespace facet::normals {

class CrossStage final : public Stage {
 public:
  static StageSpec spec();
  explicit CrossStage(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  DepthSpace space_;
  CrossOptions options_;
  int smooth_radius_px_;
  NormalSmoother smoother_;
  // Per-frame scratch kept between frames, so a stream allocates only the output images.
  cv::Mat z_;
  PixelGrid grid_;
};

}  // namespace facet::normals
