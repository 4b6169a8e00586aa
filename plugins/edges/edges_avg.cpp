#include "edges/edges_avg.hpp"

namespace facet::edges {

StageSpec AvgNormalEdges::spec() {
  return normal_edge_spec(
      "edges.avg",
      "Surface-normal edges: the angle change averaged over 8 directions.\n"
      "For each direction d (N, NE, E, SE, S, SW, W, NW), s_d = mean over k = 1..pixels of "
      "|n(p) . n(p + k*d)|; the score is the mean of the 8 s_d. Smoother, less noisy edge "
      "images than edges.max, but blunter edges (paper sec. III-A, Fig. 6). Its score is never "
      "below edges.max's, so at the same threshold it finds fewer edge pixels.");
}

AvgNormalEdges::AvgNormalEdges(const Params& params)
    : NormalEdgeStage(params, DirectionCombine::mean) {}

}  // namespace facet::edges
