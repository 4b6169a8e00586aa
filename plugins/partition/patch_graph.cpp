#include "partition/patch_graph.hpp"

#include <cstdio>

namespace facet::partition {

PatchGraph make_patch_graph(const LabelImage& objects, const GraphNodes& graph,
                            std::span<const GraphEdge> edges, std::span<const std::int32_t> group) {
  auto out = of_frame<PatchGraph>(objects);
  const auto* labels = objects.labels.ptr<std::int32_t>();
  for (const GraphNode& node : graph.nodes) {
    PatchGraph::Node entry;
    entry.blob = node.blob;
    entry.patch = node.patch;
    entry.object = labels[node.first_pixel];
    entry.size_px = node.size_px;
    entry.planar = node.planar;
    entry.plane_rms_m = node.plane_rms_m;
    entry.centre_px = {node.centre_u_px, node.centre_v_px};
    entry.normal = {node.plane.normal.x(), node.plane.normal.y(), node.plane.normal.z()};
    entry.centroid_m = {node.plane.centroid_m.x(), node.plane.centroid_m.y(),
                        node.plane.centroid_m.z()};
    out.nodes.push_back(entry);
  }
  for (const GraphEdge& edge : edges) {
    out.edges.push_back(
        {edge.a, edge.b, std::string(feature_name(edge.feature)),
         group[static_cast<std::size_t>(edge.a)] == group[static_cast<std::size_t>(edge.b)]});
  }
  return out;
}

std::string patch_graph_json(const PatchGraph& graph) {
  std::string stem;
  for (const char c : graph.frame.stem) {
    if (c == '"' || c == '\\') stem += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) stem += c;
  }
  std::string text = "{\n  \"stem\": \"" + stem + "\",\n  \"nodes\": [";
  char buffer[512];
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const PatchGraph::Node& n = graph.nodes[i];
    std::snprintf(buffer, sizeof(buffer),
                  "%s\n    {\"id\": %zu, \"blob\": %d, \"patch\": %d, \"object\": %d, "
                  "\"size_px\": %d, \"planar\": %s, \"plane_rms_m\": %.4f, "
                  "\"centre_px\": [%.1f, %.1f], \"normal\": [%.3f, %.3f, %.3f], "
                  "\"centroid_m\": [%.4f, %.4f, %.4f]}",
                  i == 0 ? "" : ",", i, n.blob, n.patch, n.object, n.size_px,
                  n.planar ? "true" : "false", n.plane_rms_m, n.centre_px[0], n.centre_px[1],
                  static_cast<double>(n.normal[0]), static_cast<double>(n.normal[1]),
                  static_cast<double>(n.normal[2]), static_cast<double>(n.centroid_m[0]),
                  static_cast<double>(n.centroid_m[1]), static_cast<double>(n.centroid_m[2]));
    text += buffer;
  }
  text += "\n  ],\n  \"edges\": [";
  for (std::size_t i = 0; i < graph.edges.size(); ++i) {
    const PatchGraph::Edge& e = graph.edges[i];
    std::snprintf(buffer, sizeof(buffer),
                  "%s\n    {\"a\": %d, \"b\": %d, \"feature\": \"%s\", \"kept\": %s}",
                  i == 0 ? "" : ",", e.a, e.b, e.feature.c_str(), e.kept ? "true" : "false");
    text += buffer;
  }
  text += "\n  ]\n}\n";
  return text;
}

}  // namespace facet::partition
