// facet::Pipeline::process on graphs/tabletop.yaml: one bundled frame, one thread, the way a
// program embeds facet. The Python module's figure (bench/python_overhead.py) is measured against
// this one; docs/performance.md has both.

#include <benchmark/benchmark.h>

#include "bundled_frames.hpp"
#include "facet/pipeline.hpp"

namespace {

const std::filesystem::path kSource = FACET_SOURCE_DIR;

void BM_PipelineTabletopFrame(benchmark::State& state) {
  facet::Pipeline pipeline(kSource / "graphs/tabletop.yaml");
  const facet::Packet depth =
      facet::Packet::make(facet::test::bundled_mosd_frame(kSource / "data/mosd", "learn0"));
  for (auto _ : state) {
    auto result = pipeline.process({{"depth", depth}});
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(BM_PipelineTabletopFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
