// partition.graph's convex ("cutfree") feature: the test of partition.convex, as graph edges.
#include <algorithm>

#include "partition/graph_edges.hpp"

namespace facet::partition {

std::string_view feature_name(EdgeFeature feature) {
  switch (feature) {
    case EdgeFeature::convex:
      return "convex";
    case EdgeFeature::coplanar:
      return "coplanar";
    case EdgeFeature::curvature:
      return "curvature";
    case EdgeFeature::floor:
      return "floor";
  }
  return "?";
}

TouchingNodes touching_nodes(const GraphNodes& graph, const PatchNeighbours& neighbours) {
  // A patch can (rarely) be cut into segments of several blobs: keep every node of a patch.
  std::int32_t max_patch = 0;
  for (const GraphNode& node : graph.nodes)
    max_patch = std::max(max_patch, node.patch);
  std::vector<std::int32_t> first(static_cast<std::size_t>(max_patch) + 2, 0);
  for (const GraphNode& node : graph.nodes) {
    if (node.patch > 0) ++first[static_cast<std::size_t>(node.patch) + 1];
  }
  for (std::size_t k = 1; k < first.size(); ++k)
    first[k] += first[k - 1];
  std::vector<std::int32_t> of_patch(static_cast<std::size_t>(first.back()));
  std::vector<std::int32_t> fill(first.begin(), first.end() - 1);
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const std::int32_t patch = graph.nodes[i].patch;
    if (patch > 0) {
      of_patch[static_cast<std::size_t>(fill[static_cast<std::size_t>(patch)]++)] =
          static_cast<std::int32_t>(i);
    }
  }
  TouchingNodes touching(graph.nodes.size());
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const std::int32_t patch = graph.nodes[i].patch;
    if (patch <= 0) continue;
    for (const std::int32_t* it = neighbours.begin(patch);
         it != nullptr && it != neighbours.end(patch); ++it) {
      if (*it > max_patch) continue;
      for (std::int32_t k = first[static_cast<std::size_t>(*it)];
           k < first[static_cast<std::size_t>(*it) + 1]; ++k) {
        const std::int32_t j = of_patch[static_cast<std::size_t>(k)];
        touching[i].push_back(j);
        touching[static_cast<std::size_t>(j)].push_back(static_cast<std::int32_t>(i));
      }
    }
  }
  for (auto& list : touching) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return touching;
}

void add_convex_edges(const BlobSegments& points, const GraphNodes& graph,
                      const PatchNeighbours& neighbours, const ConvexRule& rule,
                      std::vector<std::int32_t>& node_of_patch, std::vector<GraphEdge>& edges) {
  if (node_of_patch.size() < static_cast<std::size_t>(points.max_patch) + 1) {
    node_of_patch.assign(static_cast<std::size_t>(points.max_patch) + 1, -1);
  }
  // Junctions are tested within a blob only: patches of two blobs are apart in 3D, so they do
  // not meet at an edge of one body.
  for (std::size_t blob = 0; blob < graph.blob_begin.size(); ++blob) {
    const std::int32_t begin = graph.blob_begin[blob];
    const std::int32_t end = graph.blob_end[blob];
    for (std::int32_t i = begin; i < end; ++i) {
      const GraphNode& node = graph.nodes[static_cast<std::size_t>(i)];
      if (node.segment >= 0) node_of_patch[static_cast<std::size_t>(node.patch)] = i;
    }
    for (std::int32_t i = begin; i < end; ++i) {
      const GraphNode& a = graph.nodes[static_cast<std::size_t>(i)];
      if (a.segment < 0) continue;
      const Segment& segment_a = points.segments[static_cast<std::size_t>(a.segment)];
      for (const std::int32_t* it = neighbours.begin(a.patch);
           it != nullptr && it != neighbours.end(a.patch); ++it) {
        if (static_cast<std::size_t>(*it) >= node_of_patch.size()) continue;
        const std::int32_t j = node_of_patch[static_cast<std::size_t>(*it)];
        if (j < 0) continue;
        const GraphNode& b = graph.nodes[static_cast<std::size_t>(j)];
        if (is_convex_junction(points, segment_a, a.plane,
                               points.segments[static_cast<std::size_t>(b.segment)], b.plane,
                               rule)) {
          edges.push_back({std::min(i, j), std::max(i, j), EdgeFeature::convex});
        }
      }
    }
    for (std::int32_t i = begin; i < end; ++i) {
      const GraphNode& node = graph.nodes[static_cast<std::size_t>(i)];
      if (node.segment >= 0) node_of_patch[static_cast<std::size_t>(node.patch)] = -1;
    }
  }
}

}  // namespace facet::partition
