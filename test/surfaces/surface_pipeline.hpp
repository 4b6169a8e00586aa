#pragma once
// Runs the surface stages on test input: points and normals → edges.max/avg → grow.surfaces.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "edges/edges_avg.hpp"
#include "edges/edges_max.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "grow/grow_surfaces.hpp"
#include "surface_test_geometry.hpp"
#include "synthetic_scene.hpp"

namespace facet::test {

using Overrides = std::map<std::string, ParamValue>;

template <class EdgeStage = edges::MaxNormalEdges>
EdgeImage run_edges(const NormalImage& normals, const Overrides& params = {}) {
  testing::StageRunner<EdgeStage> runner(params);
  runner.set_input("normals", Packet::make(normals));
  runner.run();
  return runner.template output<EdgeImage>("edges");
}

struct GrowResult {
  LabelImage patches;
  PatchAdjacency adjacency;
  double unassigned_ratio = -1.0;
  std::vector<std::string> warnings;
};

inline GrowResult run_grow(const EdgeImage& edges, const PointImage& points,
                           const Overrides& params = {}) {
  testing::StageRunner<grow::GrowSurfaces> runner(params);
  runner.set_input("edges", Packet::make(edges));
  runner.set_input("points", Packet::make(points));
  runner.run();
  GrowResult result;
  result.patches = runner.output<LabelImage>("patches");
  result.adjacency = runner.output<PatchAdjacency>("adjacency");
  for (const auto& metric : runner.metrics()) {
    if (metric.name == "unassigned_ratio") result.unassigned_ratio = metric.value;
  }
  result.warnings = runner.warnings();
  return result;
}

// A rendered scene through the whole chain with default parameters.
struct SceneResult {
  RenderedScene scene;
  PointImage points;
  NormalImage normals;
  EdgeImage edges;
  GrowResult grown;
};

inline SceneResult run_scene(const SceneBuilder& builder, double max_depth_m = 4.0) {
  SceneResult result;
  result.scene = builder.render();
  result.points = points_from_depth(result.scene.depth_m, result.scene.camera, max_depth_m);
  result.normals = cross_normals(result.points);
  result.edges = run_edges(result.normals);
  result.grown = run_grow(result.edges, result.points);
  return result;
}

inline bool adjacent(const PatchAdjacency& adjacency, std::int32_t a, std::int32_t b) {
  const auto key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  for (const auto& pair : adjacency.pairs) {
    if (pair == key) return true;
  }
  return false;
}

}  // namespace facet::test
