#pragma once
// partition.bsp: blobs split into objects by the planes of their faces (paper sec. II-B f).

#include "facet/stage.hpp"
#include "partition/blob_segments.hpp"
#include "partition/bsp_partition.hpp"

namespace facet::partition {

class PartitionBsp final : public Stage {
 public:
  static StageSpec spec();
  explicit PartitionBsp(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  BspRule rule_;                    // pixel counts at reference_area_px_
  std::int64_t reference_area_px_;  // facet/algo/pixel_scale.hpp
  BspPartitioner partitioner_;
  BlobSegments segments_;  // keeps its buffers from frame to frame
};

}  // namespace facet::partition
