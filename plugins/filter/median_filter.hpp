#pragma once
// filter.median: edge-preserving denoising of depth images that never invents depth in holes.

#include "facet/stage.hpp"
#include "filter/valid_median.hpp"

namespace facet::filters {

class MedianFilter final : public Stage {
 public:
  static StageSpec spec();
  explicit MedianFilter(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  void warn_about_pinholes(const cv::Mat& depth, ProcessContext& ctx) const;

  ValidMedian median_;
  double max_pinhole_ratio_;
};

}  // namespace facet::filters
