#pragma once
// filter.median: edge-preserving denoising of depth images that never invents depth in holes.

#include "facet/stage.hpp"
#include "filters/valid_median.hpp"

namespace facet::filters {

class MedianFilter final : public Stage {
 public:
  static StageSpec spec();
  explicit MedianFilter(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  ValidMedian median_;
};

}  // namespace facet::filters
