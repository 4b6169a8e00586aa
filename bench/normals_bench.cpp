// Benchmarks of the normal stages on a real frame, one thread, 640x480, all in one run so the
// ratios between them are comparable:
//   facet_bench_normals --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// Each iteration is one stage call through StageRunner: depth conversion, normals and the
// output allocation, as in a graph.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <opencv2/core.hpp>
#include <string>

#include "bundled_frames.hpp"
#include "convert/points_stage.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "normals/cross_stage.hpp"
#include "normals/pca_stage.hpp"
#if defined(FACET_HAVE_PCL_NORMALS)
#include "normals/pcl/integral_stage.hpp"
#endif

namespace {

const std::filesystem::path kMosd = std::filesystem::path(FACET_SOURCE_DIR) / "data" / "mosd";

// learn0: a cluttered table top, 640x480 uint16 mm, with large invalid (cropped) areas.
facet::DepthImage real_frame() {
  return facet::test::bundled_mosd_frame(kMosd, "learn0");
}

// learn0 with Gaussian noise of `sigma_mm` on its valid pixels (fixed seed): a sensor noisier
// than the Kinect.
facet::DepthImage noisy_real_frame(double sigma_mm) {
  facet::DepthImage frame = real_frame();
  cv::Mat depth = frame.depth.clone();
  cv::RNG rng(7);
  for (int v = 0; v < depth.rows; ++v) {
    auto* row = depth.ptr<std::uint16_t>(v);
    for (int u = 0; u < depth.cols; ++u) {
      if (row[u] != 0) row[u] = cv::saturate_cast<std::uint16_t>(row[u] + rng.gaussian(sigma_mm));
    }
  }
  frame.depth = depth;
  return frame;
}

template <class StageT>
void run_stage(benchmark::State& state, const std::map<std::string, facet::ParamValue>& params,
               const char* output, const facet::DepthImage& frame = real_frame()) {
  facet::testing::StageRunner<StageT> runner(params);
  runner.set_input("depth", facet::Packet::make(frame));
  for (auto _ : state) {
    runner.run();
    benchmark::DoNotOptimize(runner.output_packet(output));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(frame.depth.total()));
  // The radius the automatic smoothing chose, shown beside the time.
  for (const facet::Metric& metric : runner.metrics()) {
    if (metric.name == "smooth_radius_px") state.counters["smooth_radius_px"] = metric.value;
  }
}

using facet::normals::CrossStage;

void BM_ConvertPoints(benchmark::State& state) {
  run_stage<facet::convert::PointsStage>(state, {}, "points");
}
BENCHMARK(BM_ConvertPoints)->Unit(benchmark::kMicrosecond);

void BM_CrossImageDisparity(benchmark::State& state) {
  run_stage<CrossStage>(state, {{"space", std::string("image")}}, "normals");
}
BENCHMARK(BM_CrossImageDisparity)->Unit(benchmark::kMicrosecond);

// The graphs' setting: one-sided tangents beside holes (a second pass over the NaN pixels).
void BM_CrossImageDisparityOneSided(benchmark::State& state) {
  run_stage<CrossStage>(
      state, {{"space", std::string("image")}, {"holes", std::string("one_sided")}}, "normals");
}
BENCHMARK(BM_CrossImageDisparityOneSided)->Unit(benchmark::kMicrosecond);

void BM_CrossImageMm(benchmark::State& state) {
  run_stage<CrossStage>(
      state, {{"space", std::string("image")}, {"image_depth", std::string("mm")}}, "normals");
}
BENCHMARK(BM_CrossImageMm)->Unit(benchmark::kMicrosecond);

void BM_CrossMetric(benchmark::State& state) {
  run_stage<CrossStage>(state, {{"space", std::string("metric")}}, "normals");
}
BENCHMARK(BM_CrossMetric)->Unit(benchmark::kMicrosecond);

void BM_CrossImageCentred(benchmark::State& state) {
  run_stage<CrossStage>(
      state, {{"space", std::string("image")}, {"triangle", std::string("centred")}}, "normals");
}
BENCHMARK(BM_CrossImageCentred)->Unit(benchmark::kMicrosecond);

// The authors' optional smoothing: box average over 3x3, not renormalised.
void BM_CrossImageSmooth1(benchmark::State& state) {
  run_stage<CrossStage>(
      state, {{"space", std::string("image")}, {"smooth_radius", std::int64_t{1}}}, "normals");
}
BENCHMARK(BM_CrossImageSmooth1)->Unit(benchmark::kMicrosecond);

void BM_CrossImageSmooth1Renormalized(benchmark::State& state) {
  run_stage<CrossStage>(
      state,
      {{"space", std::string("image")}, {"smooth_radius", std::int64_t{1}}, {"renormalize", true}},
      "normals");
}
BENCHMARK(BM_CrossImageSmooth1Renormalized)->Unit(benchmark::kMicrosecond);

// The shipped graph's setting with its automatic smoothing: on learn0 (Kinect noise) only the
// measure runs; with 6 mm of noise the frame is measured and smoothed.
const std::map<std::string, facet::ParamValue> kTabletopCross{
    {"space", std::string("image")},
    {"holes", std::string("one_sided")},
    {"auto_smooth_max_radius", std::int64_t{2}}};

void BM_CrossTabletopAutoSmooth(benchmark::State& state) {
  run_stage<CrossStage>(state, kTabletopCross, "normals");
}
BENCHMARK(BM_CrossTabletopAutoSmooth)->Unit(benchmark::kMicrosecond);

void BM_CrossTabletopAutoSmoothNoisy(benchmark::State& state) {
  run_stage<CrossStage>(state, kTabletopCross, "normals", noisy_real_frame(6.0));
}
BENCHMARK(BM_CrossTabletopAutoSmoothNoisy)->Unit(benchmark::kMicrosecond);

void BM_CrossTabletopNoisyUnsmoothed(benchmark::State& state) {
  run_stage<CrossStage>(state,
                        {{"space", std::string("image")}, {"holes", std::string("one_sided")}},
                        "normals", noisy_real_frame(6.0));
}
BENCHMARK(BM_CrossTabletopNoisyUnsmoothed)->Unit(benchmark::kMicrosecond);

void BM_PcaImage(benchmark::State& state) {
  run_stage<facet::normals::PcaStage>(
      state, {{"space", std::string("image")}, {"window", std::int64_t{state.range(0)}}},
      "normals");
}
BENCHMARK(BM_PcaImage)->ArgName("window")->Arg(3)->Arg(5)->Unit(benchmark::kMicrosecond);

void BM_PcaMetric(benchmark::State& state) {
  run_stage<facet::normals::PcaStage>(
      state, {{"space", std::string("metric")}, {"window", std::int64_t{state.range(0)}}},
      "normals");
}
BENCHMARK(BM_PcaMetric)->ArgName("window")->Arg(3)->Arg(5)->Unit(benchmark::kMicrosecond);

#if defined(FACET_HAVE_PCL_NORMALS)
// PCL at its defaults (average_3d_gradient, smoothing size 10), and its covariance method.
void BM_IntegralPcl(benchmark::State& state) {
  run_stage<facet::normals::IntegralStage>(state, {}, "normals");
}
BENCHMARK(BM_IntegralPcl)->Unit(benchmark::kMicrosecond);

void BM_IntegralPclCovariance(benchmark::State& state) {
  run_stage<facet::normals::IntegralStage>(state, {{"method", std::string("covariance")}},
                                           "normals");
}
BENCHMARK(BM_IntegralPclCovariance)->Unit(benchmark::kMicrosecond);
#endif

}  // namespace
BENCHMARK_MAIN();
