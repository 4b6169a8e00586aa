#pragma once
// edges.avg: the averaging variant of the surface-normal edge filter (paper Fig. 6).

#include "edges/normal_edge_stage.hpp"

namespace facet::edges {

class AvgNormalEdges final : public NormalEdgeStage {
 public:
  static StageSpec spec();
  explicit AvgNormalEdges(const Params& params);
};

}  // namespace facet::edges
