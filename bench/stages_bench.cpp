// Benchmarks of the bundled stages on real frames, one thread:
//   facet_bench_stages --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "filter/valid_median.hpp"
#include "io/frames_source.hpp"

namespace {

const std::filesystem::path kMosd = std::filesystem::path(FACET_SOURCE_DIR) / "data" / "mosd";

// learn0: 640x480, about 40% of the pixels are holes (mOSD crops floor and walls to invalid),
// so both the all-valid and the mixed windows are exercised.
cv::Mat real_frame() {
  const auto file = kMosd / "depth" / "learn0.png";
  cv::Mat depth = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  if (depth.type() != CV_16UC1) throw std::runtime_error("cannot read " + file.string());
  return depth;
}

void BM_MedianFilterMm(benchmark::State& state) {
  const cv::Mat depth = real_frame();
  facet::filters::ValidMedian median(static_cast<int>(state.range(0)), state.range(1) != 0);
  for (auto _ : state) {
    cv::Mat out = median.apply(depth);
    benchmark::DoNotOptimize(out.data);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(depth.total()));
}
BENCHMARK(BM_MedianFilterMm)
    ->ArgNames({"size", "fill_holes"})
    ->Args({3, 0})
    ->Args({5, 0})
    ->Args({3, 1})
    ->Unit(benchmark::kMicrosecond);

void BM_MedianFilterMetres(benchmark::State& state) {
  cv::Mat depth;
  real_frame().convertTo(depth, CV_32F, 0.001);
  facet::filters::ValidMedian median(static_cast<int>(state.range(0)), false);
  for (auto _ : state) {
    cv::Mat out = median.apply(depth);
    benchmark::DoNotOptimize(out.data);
  }
}
BENCHMARK(BM_MedianFilterMetres)->ArgName("size")->Arg(3)->Arg(5)->Unit(benchmark::kMicrosecond);

// io.frames: PNG decode of depth and labels, checks, packet creation; the six bundled frames
// in a loop.
void BM_FramesSourceDecode(benchmark::State& state) {
  facet::testing::StageRunner<facet::io::FramesSource> source(
      {{"path", kMosd.string()}, {"loop", true}});
  for (auto _ : state) {
    source.run();
    benchmark::DoNotOptimize(source.output_packet("depth").address());
  }
}
BENCHMARK(BM_FramesSourceDecode)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
