#include "edges/edges_max.hpp"

namespace facet::edges {

StageSpec MaxNormalEdges::spec() {
  return normal_edge_spec(
      "edges.max",
      "Surface-normal edges: the largest angle change over 8 directions decides.\n"
      "For each direction d (N, NE, E, SE, S, SW, W, NW), s_d = mean over k = 1..pixels of "
      "|n(p) . n(p + k*d)|; the score is the minimum of the 8 s_d (paper eq. 3 and 4). The "
      "absolute value treats an obtuse angle like its supplement. Sharper edges than edges.avg; "
      "the variant the paper selected.");
}

MaxNormalEdges::MaxNormalEdges(const Params& params)
    : NormalEdgeStage(params, DirectionCombine::min) {}

}  // namespace facet::edges
