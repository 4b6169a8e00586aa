#pragma once
// What edges.max and edges.avg share: their ports and parameters, and process().
// The two stages differ only in how the 8 direction scores are combined.

#include <string>

#include "edges/normal_edge_score.hpp"
#include "facet/stage.hpp"

namespace facet::edges {

// The spec both variants declare; `name` and `doc` are the variant's own.
StageSpec normal_edge_spec(std::string name, std::string doc);

class NormalEdgeStage : public Stage {
 public:
  NormalEdgeStage(const Params& params, DirectionCombine combine);
  void process(ProcessContext& ctx) override;

 private:
  NormalEdgeScorer scorer_;
  float threshold_;
};

}  // namespace facet::edges
