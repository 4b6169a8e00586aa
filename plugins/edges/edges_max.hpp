#pragma once
// edges.max: the paper's surface-normal edge filter (eq. 4), the strongest angle change wins.

#include "edges/normal_edge_stage.hpp"

namespace facet::edges {

class MaxNormalEdges final : public NormalEdgeStage {
 public:
  static StageSpec spec();
  explicit MaxNormalEdges(const Params& params);
};

}  // namespace facet::edges
