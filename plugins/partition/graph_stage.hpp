#pragma once
// partition.graph: objects as the groups of a graph of surface patches, joined by convex
// junctions, by one plane seen on both sides of an occluder, and by one curved surface (the
// authors' later algorithm); weak bridges between groups are cut.

#include <cstdint>
#include <vector>

#include "facet/stage.hpp"
#include "partition/blob_segments.hpp"
#include "partition/convex_merge.hpp"
#include "partition/graph_cores.hpp"
#include "partition/graph_cut.hpp"
#include "partition/graph_edges.hpp"
#include "partition/graph_front_bodies.hpp"
#include "partition/graph_nodes.hpp"
#include "partition/graph_span_split.hpp"
#include "partition/graph_steps.hpp"

namespace facet::partition {

struct GraphRule {
  NodeRule nodes;
  bool convex = true;
  ConvexRule convex_rule;
  bool coplanar = true;
  CoplanarRule coplanar_rule;
  bool curvature = true;
  CurvatureRule curvature_rule;
  bool floor = true;
  FloorRule floor_rule;
  StepRule steps;
  SpanSplitRule span_split;
  CutRule cut;
};

class PartitionGraph final : public Stage {
 public:
  static StageSpec spec();
  explicit PartitionGraph(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  // The rules whose pixel counts and widths scale with the image (facet/algo/pixel_scale.hpp).
  struct FrameRules {
    NodeRule nodes;
    ConvexRule convex;
    CoreRule core;
    FrontBodyRule front;
  };
  FrameRules rules_for(cv::Size image) const;

  GraphRule rule_;
  bool emit_graph_;
  std::int64_t reference_area_px_;  // pixel counts and widths are given for this image area
  CoreRule core_rule_;
  cv::Mat node_of_pixel_;
  std::vector<FittedPlane> face_planes_;
  CoreBuffers core_buffers_;
  FrontBodyRule front_rule_;
  FacesOfObject faces_of_object_;
  FrontBodyBuffers front_buffers_;
  // Kept from frame to frame for their buffers only.
  BlobSegments segments_;
  PatchNeighbours neighbours_;
  GraphNodes graph_;
  GraphCut cut_;
  std::vector<GraphEdge> edges_;
  std::vector<std::int32_t> node_of_patch_;
  std::vector<std::int32_t> split_of_node_;
};

}  // namespace facet::partition
