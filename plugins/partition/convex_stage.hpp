#pragma once
// partition.convex: objects as groups of patches joined at convex junctions (the authors' later
// "cutfree" test), an alternative to partition.bsp.

#include "facet/stage.hpp"
#include "partition/blob_segments.hpp"
#include "partition/convex_merge.hpp"

namespace facet::partition {

class PartitionConvex final : public Stage {
 public:
  static StageSpec spec();
  explicit PartitionConvex(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  ConvexRule rule_;                 // min_patch_px at reference_area_px_
  std::int64_t reference_area_px_;  // facet/algo/pixel_scale.hpp
  ConvexMerger merger_;
  BlobSegments segments_;  // keeps its buffers from frame to frame
  PatchNeighbours neighbours_;
};

}  // namespace facet::partition
