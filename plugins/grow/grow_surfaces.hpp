#pragma once
// grow.surfaces: region growing of the non-edge pixels into surface patches (paper sec. II-A c),
// assignment of edge pixels to the patches, and which patches touch.

#include <cstdint>

#include "facet/stage.hpp"
#include "grow/edge_assignment.hpp"
#include "grow/surface_regions.hpp"

namespace facet::grow {

class GrowSurfaces final : public Stage {
 public:
  static StageSpec spec();
  explicit GrowSurfaces(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  int connectivity_;
  algo::RegionSizeRule region_size_;
  std::int64_t reference_area_px_;  // pixel counts are given for this image area
  double max_unassigned_ratio_;
  // Both keep their buffers from frame to frame.
  SurfaceRegionLabeler regions_;
  EdgeAssignment assignment_;
};

}  // namespace facet::grow
