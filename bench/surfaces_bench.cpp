// Benchmarks of the surface-patch stages on a real frame, one thread:
//   facet_bench_surfaces --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// Input: mOSD learn0 (640x480, Kinect-type). The edge benchmarks and `grow.surfaces` use metric
// cross-product normals (r = 2) computed by the test helper; `grow.surfaces/tabletop` grows the
// edges the faces and tabletop graphs produce (3x3 median, image-space cross normals on Kinect
// disparity, edges.max over 3 px at 0.85), prepared once by those stages.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>

#include "edges/edges_avg.hpp"
#include "edges/edges_max.hpp"
#include "faces_input.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "grow/grow_surfaces.hpp"
#include "surface_test_geometry.hpp"

namespace {

const std::filesystem::path kMosd = std::filesystem::path(FACET_SOURCE_DIR) / "data" / "mosd";

const facet::test::RealFrame& frame() {
  static const facet::test::RealFrame loaded = facet::test::load_mosd_frame(kMosd, "learn0");
  return loaded;
}

// range(1): invalid_neighbours, 0 = edge (the default), 1 = skip.
template <class EdgeStage>
void BM_Edges(benchmark::State& state) {
  facet::testing::StageRunner<EdgeStage> runner(
      {{"pixels", std::int64_t{state.range(0)}},
       {"invalid_neighbours", std::string(state.range(1) == 0 ? "edge" : "skip")}});
  runner.set_input("normals", facet::Packet::make(frame().normals));
  for (auto _ : state) {
    runner.run();
    benchmark::DoNotOptimize(runner.output_packet("edges").address());
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(frame().normals.normals.total()));
}
BENCHMARK(BM_Edges<facet::edges::MaxNormalEdges>)
    ->Name("edges.max")
    ->ArgNames({"pixels", "skip_invalid"})
    ->ArgsProduct({{3, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Edges<facet::edges::AvgNormalEdges>)
    ->Name("edges.avg")
    ->ArgNames({"pixels", "skip_invalid"})
    ->ArgsProduct({{3, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// grow.surfaces on the edges of edges.max (pixels 3, threshold 0.89: the metric-normal value
// the prototype measured; at 0.85 learn0 has fewer, larger patches).
void BM_GrowSurfaces(benchmark::State& state) {
  facet::testing::StageRunner<facet::edges::MaxNormalEdges> edges({{"threshold", 0.89}});
  edges.set_input("normals", facet::Packet::make(frame().normals));
  edges.run();
  facet::testing::StageRunner<facet::grow::GrowSurfaces> grow(
      {{"connectivity", std::int64_t{state.range(0)}}});
  grow.set_input("edges", edges.output_packet("edges"));
  grow.set_input("points", facet::Packet::make(frame().points));
  for (auto _ : state) {
    grow.run();
    benchmark::DoNotOptimize(grow.output_packet("patches").address());
  }
  grow.run();
  for (const auto& metric : grow.metrics())
    state.counters[metric.name] = metric.value;
}
BENCHMARK(BM_GrowSurfaces)
    ->Name("grow.surfaces")
    ->ArgName("connectivity")
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond);

// range(0): 1 = graphs/tabletop.yaml's far region rule (min_size_reference_depth_m 1.0,
// min_size_far_px 50), 0 = the stage's default fixed count.
void BM_GrowSurfacesTabletop(benchmark::State& state) {
  static const facet::bench::FacesInput input = facet::bench::faces_input("learn0");
  std::map<std::string, facet::ParamValue> params;
  if (state.range(0) != 0) {
    params = {{"min_size_reference_depth_m", 1.0}, {"min_size_far_px", std::int64_t{50}}};
  }
  facet::testing::StageRunner<facet::grow::GrowSurfaces> grow(params);
  grow.set_input("edges", input.edges);
  grow.set_input("points", input.points);
  for (auto _ : state) {
    grow.run();
    benchmark::DoNotOptimize(grow.output_packet("patches").address());
  }
  grow.run();
  for (const auto& metric : grow.metrics())
    state.counters[metric.name] = metric.value;
}
BENCHMARK(BM_GrowSurfacesTabletop)
    ->Name("grow.surfaces/tabletop")
    ->ArgName("far_rule")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
