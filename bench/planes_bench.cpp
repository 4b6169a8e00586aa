// Benchmarks of the support-plane and blob stages on a real frame, one thread:
//   facet_bench_planes --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// Input: mOSD learn0 (640x480), prepared in the setup by the faces stages with the
// objects_planes graph's settings (3x3 median, points, image-space cross normals, edges.max); the
// patches are the connected non-edge regions of at least 100 px (grow.surfaces without its
// assignment of edge pixels, which only moves a patch's border), so that this benchmark does not
// depend on the region-growing plugin.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "blobs/grow_blobs.hpp"
#include "faces_input.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "planes/support_planes.hpp"

namespace {

struct Prepared {
  facet::Packet points;
  facet::Packet patches;
};

Prepared prepare(const std::string& stem) {
  const facet::bench::FacesInput input = facet::bench::faces_input(stem);
  const auto& edge = *input.edges.get_if<facet::EdgeImage>();
  const auto& xyz = *input.points.get_if<facet::PointImage>();
  cv::Mat surface = edge.mask == 0;
  for (int row = 0; row < surface.rows; ++row) {
    for (int col = 0; col < surface.cols; ++col) {
      if (!std::isfinite(xyz.points.at<cv::Vec3f>(row, col)[2]))
        surface.at<unsigned char>(row, col) = 0;
    }
  }
  facet::LabelImage patches;
  static_cast<facet::FrameHeader&>(patches) = xyz;
  cv::Mat stats;
  cv::Mat centroids;
  const int count =
      cv::connectedComponentsWithStats(surface, patches.labels, stats, centroids, 4, CV_32S);
  std::vector<std::int32_t> id(static_cast<std::size_t>(count), 0);
  for (int i = 1; i < count; ++i) {
    if (stats.at<int>(i, cv::CC_STAT_AREA) >= 100) id[i] = ++patches.count;
  }
  patches.labels.forEach<std::int32_t>([&](std::int32_t& label, const int*) { label = id[label]; });
  return {input.points, facet::Packet::make(std::move(patches))};
}

const Prepared& frame() {
  static const Prepared prepared = prepare("learn0");
  return prepared;
}

// range(0): planes_per_patch (2, the default; 1, the paper's one plane per patch).
void BM_SupportPlanes(benchmark::State& state) {
  facet::testing::StageRunner<facet::planes::SupportPlaneStage> planes(
      {{"planes_per_patch", std::int64_t{state.range(0)}}});
  planes.set_input("patches", frame().patches);
  planes.set_input("points", frame().points);
  for (auto _ : state) {
    planes.run();
    benchmark::DoNotOptimize(planes.output_packet("patches").address());
  }
  for (const auto& metric : planes.metrics())
    state.counters[metric.name] = metric.value;
}
BENCHMARK(BM_SupportPlanes)
    ->Name("planes.support")
    ->ArgName("planes_per_patch")
    ->Arg(2)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);

void BM_GrowBlobs(benchmark::State& state) {
  facet::testing::StageRunner<facet::planes::SupportPlaneStage> planes;
  planes.set_input("patches", frame().patches);
  planes.set_input("points", frame().points);
  planes.run();
  facet::testing::StageRunner<facet::blobs::GrowBlobs> blobs;
  blobs.set_input("patches", planes.output_packet("patches"));
  blobs.set_input("points", frame().points);
  blobs.set_input("planes", planes.output_packet("planes"));
  for (auto _ : state) {
    blobs.run();
    benchmark::DoNotOptimize(blobs.output_packet("blobs").address());
  }
  for (const auto& metric : blobs.metrics())
    state.counters[metric.name] = metric.value;
}
BENCHMARK(BM_GrowBlobs)->Name("grow.blobs")->Unit(benchmark::kMillisecond);

// Both stages as the graph runs them.
void BM_PlanesAndBlobs(benchmark::State& state) {
  facet::testing::StageRunner<facet::planes::SupportPlaneStage> planes;
  facet::testing::StageRunner<facet::blobs::GrowBlobs> blobs;
  planes.set_input("patches", frame().patches);
  planes.set_input("points", frame().points);
  blobs.set_input("points", frame().points);
  for (auto _ : state) {
    planes.run();
    blobs.set_input("patches", planes.output_packet("patches"));
    blobs.set_input("planes", planes.output_packet("planes"));
    blobs.run();
    benchmark::DoNotOptimize(blobs.output_packet("blobs").address());
  }
}
BENCHMARK(BM_PlanesAndBlobs)->Name("planes.support+grow.blobs")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
