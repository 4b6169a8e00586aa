#pragma once
// grow.blobs: object candidates as Euclidean blobs of the points left after the support planes
// (paper sec. II-B e).

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>

#include "blobs/blob_support.hpp"
#include "facet/algo/neighbour_gate.hpp"
#include "facet/algo/region_size_rule.hpp"
#include "facet/stage.hpp"

namespace facet::blobs {

class GrowBlobs final : public Stage {
 public:
  static StageSpec spec();
  explicit GrowBlobs(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  algo::NeighbourGate gate_;
  algo::RegionSizeRule size_;
  std::int64_t reference_area_px_;  // pixel counts are given for this image area
  bool edge_pixels_;
  BackgroundBlobRule rule_;
  std::optional<Eigen::AlignedBox3f> workspace_;
};

}  // namespace facet::blobs
