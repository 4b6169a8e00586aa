// facet::Pipeline::process on graphs/tabletop.yaml: one bundled frame, one thread, the way a
// program embeds facet. The Python module's figure (bench/python_overhead.py) is measured against
// this one; docs/performance.md has both.

#include <benchmark/benchmark.h>

#include <chrono>
#include <utility>
#include <vector>

#include "bundled_frames.hpp"
#include "facet/framework/statistics.hpp"
#include "facet/pipeline.hpp"

namespace {

const std::filesystem::path kSource = FACET_SOURCE_DIR;

void BM_PipelineTabletopFrame(benchmark::State& state) {
  facet::Pipeline pipeline(kSource / "graphs/tabletop.yaml");
  const facet::Packet depth =
      facet::Packet::make(facet::test::bundled_mosd_frame(kSource / "data/mosd", "learn0"));
  // Besides the time per call, the median time of a call outside its stage calls (gathering
  // inputs, running the graph's bookkeeping, collecting outputs): the part of the C++ API's cost
  // that the Python module's "outside the stages" figure is compared with, since it hardly
  // depends on how fast the machine runs the stages that sitting.
  std::vector<double> outside_ms;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    auto result = pipeline.process({{"depth", depth}});
    const double call_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    double stages_ms = 0.0;
    for (const facet::StageTiming& timing : result.timings)
      stages_ms += timing.ms;
    outside_ms.push_back(call_ms - stages_ms);
    benchmark::DoNotOptimize(result);
  }
  state.counters["outside_stages_ms"] = facet::median(std::move(outside_ms));
}

BENCHMARK(BM_PipelineTabletopFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
