#pragma once
// The surface-patch graph of partition.graph as a packet, for a person to look at (written as
// JSON by io.patch_graph): which patches were nodes, which features joined them, what the cut
// kept.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "facet/packet.hpp"
#include "facet/types/frame.hpp"
#include "facet/types/images.hpp"
#include "partition/graph_edges.hpp"
#include "partition/graph_nodes.hpp"

namespace facet::partition {

struct PatchGraph : FrameHeader {
  struct Node {
    std::int32_t blob = 0;
    std::int32_t patch = 0;   // 0: a blob without a usable patch
    std::int32_t object = 0;  // id in the stage's objects output
    std::int32_t size_px = 0;
    bool planar = false;
    double plane_rms_m = 0.0;
    std::array<double, 2> centre_px{};  // mean pixel (u, v)
    std::array<float, 3> normal{};
    std::array<float, 3> centroid_m{};
  };
  struct Edge {
    std::int32_t a = 0;  // node indices
    std::int32_t b = 0;
    std::string feature;  // convex, coplanar, curvature
    bool kept = false;    // both ends in one object after the cut
  };
  std::vector<Node> nodes;
  std::vector<Edge> edges;
};

PatchGraph make_patch_graph(const LabelImage& objects, const GraphNodes& graph,
                            std::span<const GraphEdge> edges, std::span<const std::int32_t> group);

// The graph as JSON text (fixed precision, deterministic).
std::string patch_graph_json(const PatchGraph& graph);

}  // namespace facet::partition

FACET_TYPE_KEY(facet::partition::PatchGraph, "facet.partition.PatchGraph/1");
