// Partition stages on synthetic tabletop scenes with a growing number of faces, every object in
// one blob (the costly case: the whole scene must be partitioned by faces).
//
//   build/bin/facet_bench_partition --benchmark_repetitions=5 --benchmark_report_aggregates_only

#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "partition/bsp_stage.hpp"
#include "partition/convex_stage.hpp"
#include "partition/graph_stage.hpp"
#include "partition_scene.hpp"

namespace {

using facet::test::PartitionInput;

// Rows of boxes standing side by side, some with a smaller box on top, until the scene shows
// at least `faces` faces. Three faces per box are visible from the tilted camera.
PartitionInput scene_with_faces(int faces) {
  facet::test::Tabletop table(55.0);
  const int boxes = std::max(1, (faces + 2) / 3);
  const int per_row = std::max(2, static_cast<int>(std::ceil(std::sqrt(boxes * 1.5))));
  const double pitch_m = 0.6 / per_row;
  int placed = 0;
  for (int row = 0; placed < boxes; ++row) {
    for (int col = 0; col < per_row && placed < boxes; ++col, ++placed) {
      const double half = 0.5 * pitch_m;
      const double x = -0.3 + (col + 0.5) * pitch_m;
      const double y = -0.2 + (row + 0.5) * pitch_m;
      const double height = half * (0.6 + 0.15 * ((row + col) % 3));
      table.box(x, y, {half, half, height}, 8.0 * ((row * 7 + col) % 5));
    }
  }
  return facet::test::one_blob(table.builder().render());
}

template <class Stage>
void run_stage(benchmark::State& state,
               const std::map<std::string, facet::ParamValue>& overrides = {}) {
  const PartitionInput input = scene_with_faces(static_cast<int>(state.range(0)));
  facet::testing::StageRunner<Stage> runner(overrides);
  runner.set_input("blobs", facet::Packet::make(input.blobs));
  runner.set_input("patches", facet::Packet::make(input.patches));
  runner.set_input("adjacency", facet::Packet::make(input.adjacency));
  runner.set_input("points", facet::Packet::make(input.points));
  for (auto _ : state)
    runner.run();
  std::vector<int> patch_ids(input.patches.labels.begin<int>(), input.patches.labels.end<int>());
  std::sort(patch_ids.begin(), patch_ids.end());
  patch_ids.erase(std::unique(patch_ids.begin(), patch_ids.end()), patch_ids.end());
  state.counters["faces"] = static_cast<double>(patch_ids.size()) - 1.0;
  state.counters["objects"] = runner.template output<facet::LabelImage>("objects").count;
  state.counters["blob_px"] = cv::countNonZero(input.blobs.labels);
}

void BM_PartitionBsp(benchmark::State& state) {
  run_stage<facet::partition::PartitionBsp>(state);
}
void BM_PartitionConvex(benchmark::State& state) {
  run_stage<facet::partition::PartitionConvex>(state);
}
void BM_PartitionGraph(benchmark::State& state) {
  run_stage<facet::partition::PartitionGraph>(state);
}

// The same without the unclaimed cores, for their cost in one sitting.
void BM_PartitionGraphNoCores(benchmark::State& state) {
  run_stage<facet::partition::PartitionGraph>(state, {{"unclaimed_core_radius_px", 0.0}});
}

// With the bodies in front of a flat face, as graphs/tabletop.yaml runs it, for its cost in one
// sitting.
void BM_PartitionGraphFrontBodies(benchmark::State& state) {
  run_stage<facet::partition::PartitionGraph>(state, {{"front_body_margin_m", 0.015}});
}

BENCHMARK(BM_PartitionBsp)->Arg(5)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PartitionConvex)->Arg(5)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);
// The graph stage, with and without its unclaimed cores, also on 200 faces.
void up_to_200_faces(benchmark::internal::Benchmark* benchmark) {
  for (const int faces : {5, 20, 50, 100, 200})
    benchmark->Arg(faces);
  benchmark->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_PartitionGraph)->Apply(up_to_200_faces);
BENCHMARK(BM_PartitionGraphNoCores)->Apply(up_to_200_faces);
BENCHMARK(BM_PartitionGraphFrontBodies)->Apply(up_to_200_faces);

}  // namespace
BENCHMARK_MAIN();
