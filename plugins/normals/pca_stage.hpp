#pragma once
// normals.pca: surface normals by PCA of a k x k window (the paper's Table I alternative).

#include <opencv2/core/mat.hpp>

#include "facet/stage.hpp"
#include "normals/depth_space.hpp"
#include "normals/pca_kernel.hpp"

namespace facet::normals {

class PcaStage final : public Stage {
 public:
  static StageSpec spec();
  explicit PcaStage(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  DepthSpace space_;
  PcaNormals pca_;
  cv::Mat z_;
  PixelGrid grid_;
};

}  // namespace facet::normals
