#pragma once
// normals.cross: the paper's surface normals, from the cross product of neighbours at radius r.

#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/stage.hpp"
#include "normals/cross_kernel.hpp"
#include "normals/depth_space.hpp"
#include "normals/normal_noise.hpp"
#include "normals/normal_smoothing.hpp"

namespace facet::normals {

class CrossStage final : public Stage {
 public:
  static StageSpec spec();
  explicit CrossStage(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  void smooth_if_noisy(ProcessContext& ctx, cv::Mat& normals);
  void warn_if_still_noisy(ProcessContext& ctx, const cv::Mat& smoothed);

  DepthSpace space_;
  CrossOptions options_;
  int smooth_radius_px_;
  NormalSmoother smoother_;
  int auto_max_radius_px_;
  double auto_min_gain_;
  NoisyPairRule noisy_pairs_;                   // measured against the edge filter's angle
  std::vector<NormalSmoother> auto_smoothers_;  // radius 1, 2, ... (renormalised)
  // Per-frame scratch kept between frames, so a stream allocates only the output images.
  cv::Mat z_;
  PixelGrid grid_;
  std::vector<cv::Mat> smoothed_;  // per radius of the ladder, kept between frames
};

}  // namespace facet::normals
