// Superquadric and PCA-box fits on ray-cast objects standing on a table, one thread. The fit alone
// (per object, from the stage's own initial box) and the whole stage on a one-object frame.
//   build-shape/bin/facet_bench_shape --benchmark_repetitions=10 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include "facet/testing/stage_runner.hpp"
#include "shape/object_models.hpp"
#include "shape/pca_box.hpp"
#include "shape/pca_box_stage.hpp"
#include "shape/superquadric_fit.hpp"
#include "shape/superquadric_stage.hpp"
#include "tabletop_scene.hpp"

namespace {

using facet::test::TabletopShape;

// Object size scaled by range(1)/100 of a 12 x 7 x 10 cm box (or a 8 cm wide, 14 cm tall
// cylinder): 50 → ~2.5k px, 100 → ~10k px, 140 → ~20k px at 0.9 m.
facet::test::TabletopScene scene_for(const benchmark::State& state) {
  const double scale = static_cast<double>(state.range(1)) / 100.0;
  const bool box = state.range(0) == 0;
  const Eigen::Vector3d half_m =
      box ? Eigen::Vector3d(0.06, 0.035, 0.05) * scale : Eigen::Vector3d(0.04, 0.04, 0.07) * scale;
  return facet::test::render_tabletop(box ? TabletopShape::box : TabletopShape::cylinder, half_m,
                                      50.0);
}

void BM_SuperquadricFit(benchmark::State& state) {
  const auto scene = scene_for(state);
  auto objects =
      facet::shape::describe_objects(scene.objects, scene.points, &scene.planes, 0.02, 0.3);
  const auto& object = objects.at(0);
  const facet::OrientedBox initial =
      facet::shape::fit_supported_box(object.points_m, *object.support);
  const facet::shape::SuperquadricFitOptions options;
  for (auto _ : state) {
    auto fit = facet::shape::fit_superquadric(object.points_m, initial, object.support, options);
    benchmark::DoNotOptimize(fit);
  }
  state.counters["pixels"] = static_cast<double>(object.model.pixel_count);
}

template <class StageT>
void BM_Stage(benchmark::State& state) {
  const auto scene = scene_for(state);
  facet::testing::StageRunner<StageT> runner;
  runner.set_input("objects", facet::Packet::make(scene.objects));
  runner.set_input("points", facet::Packet::make(scene.points));
  runner.set_input("planes", facet::Packet::make(scene.planes));
  for (auto _ : state)
    runner.run();
  state.counters["pixels"] = static_cast<double>(cv::countNonZero(scene.objects.labels));
}

void shapes_and_sizes(benchmark::internal::Benchmark* bench) {
  bench->ArgNames({"cylinder", "scale"});
  for (const int shape : {0, 1}) {
    for (const int scale : {50, 100, 140})
      bench->Args({shape, scale});
  }
  bench->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_SuperquadricFit)->Apply(shapes_and_sizes);
BENCHMARK(BM_Stage<facet::shape::SuperquadricStage>)->Apply(shapes_and_sizes);
BENCHMARK(BM_Stage<facet::shape::PcaBoxStage>)->Apply(shapes_and_sizes);

}  // namespace

BENCHMARK_MAIN();
