// io.synthetic's presets: what a generated frame costs, and what the whole tabletop graph
// (graphs/tabletop.yaml, the bundled plugins of this build) costs per frame on each preset.
//
//   build/bin/facet_bench_synthetic --benchmark_repetitions=5 --benchmark_report_aggregates_only

#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>

#include "bundled_plugins.hpp"
#include "facet/framework/diagnostics.hpp"
#include "facet/framework/executor.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/validated_graph.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "synthetic/scene_layout.hpp"
#include "synthetic/synthetic_source.hpp"
#include "temp_dir.hpp"

namespace {

using facet::test::bundled_plugins;

const std::string& preset_of(const benchmark::State& state) {
  return facet::synthetic::preset_names().at(static_cast<std::size_t>(state.range(0)));
}

// Loads and validates a shipped graph with graph params; aborts the benchmark on errors.
facet::ValidatedGraph shipped_graph(const std::string& name,
                                    const std::map<std::string, std::string>& params,
                                    benchmark::State& state, bool& ok) {
  facet::Diagnostics diagnostics;
  facet::LoadOptions options;
  options.params = params;
  const facet::GraphSpec spec = facet::load_graph_file(
      std::filesystem::path(FACET_SOURCE_DIR) / "graphs" / name, options, diagnostics);
  facet::ValidatedGraph graph = facet::validate_graph(spec, bundled_plugins(), diagnostics);
  ok = !diagnostics.has_errors();
  if (!ok) state.SkipWithError(diagnostics.str().c_str());
  return graph;
}

// One static scene, a new noisy frame per iteration (the layout is drawn once, in open()).
void BM_SyntheticFrame(benchmark::State& state) {
  const std::string& preset = preset_of(state);
  facet::testing::StageRunner<facet::synthetic::SyntheticSource> runner(
      {{"preset", preset}, {"frames", std::int64_t{0}}});
  runner.run();
  for (auto _ : state)
    runner.run();
  state.SetLabel(preset);
  state.counters["objects"] = runner.output<facet::LabelImage>("labels").count;
}

// graphs/tabletop.yaml on 5 frames of the preset (written once by graphs/synthetic.yaml),
// including its file reading and writing; time per frame.
void BM_TabletopGraph(benchmark::State& state) {
  const std::string& preset = preset_of(state);
  state.SetLabel(preset);
  const facet::test::TempDir dir("facet-bench-synthetic");
  const std::string scenes = (dir.path() / "scenes").string();
  constexpr int kFrames = 5;
  bool ok = false;
  const auto writer = shipped_graph(
      "synthetic.yaml",
      {{"preset", preset}, {"frames", std::to_string(kFrames)}, {"output", scenes}}, state, ok);
  if (!ok) return;
  facet::SequentialExecutor(writer).run();
  const auto tabletop = shipped_graph(
      "tabletop.yaml", {{"input", scenes}, {"output", (dir.path() / "out").string()}}, state, ok);
  if (!ok) return;
  for (auto _ : state) {
    facet::SequentialExecutor executor(tabletop);
    benchmark::DoNotOptimize(executor.run().frames);
  }
  // items_per_second: frames per second through the whole graph.
  state.SetItemsProcessed(state.iterations() * kFrames);
}

BENCHMARK(BM_SyntheticFrame)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TabletopGraph)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
