// The PNG files every frame reads and writes, facet's codec against OpenCV's (libpng + zlib),
// on a bundled mOSD frame, one thread:
//   facet_bench_png --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// Inputs: the depth frame as io.frames reads it, its ground-truth labels as io.labels writes
// them, and the colour overlay io.overlay draws of the two.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <vector>

#include "io/overlay_sink.hpp"
#include "io/png_codec.hpp"

namespace {

namespace png = facet::io::png;
const std::filesystem::path kMosd = std::filesystem::path(FACET_SOURCE_DIR) / "data" / "mosd";

cv::Mat read(const std::filesystem::path& file) {
  cv::Mat image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  if (image.empty()) throw std::runtime_error("cannot read " + file.string());
  return image;
}

enum Input { kDepth = 0, kLabels = 1, kOverlay = 2 };

cv::Mat input(int which) {
  const cv::Mat depth = read(kMosd / "depth" / "learn0.png");
  cv::Mat labels;
  read(kMosd / "label" / "learn0.png").convertTo(labels, CV_32S);
  if (which == kDepth) return depth;
  if (which == kLabels) {
    cv::Mat ids;
    labels.convertTo(ids, CV_16U);
    return ids;
  }
  return facet::io::render_overlay(depth, labels, cv::Mat(), facet::io::OverlayStyle{});
}

void set_label(benchmark::State& state) {
  static const char* const names[] = {"depth 16-bit", "labels 16-bit", "overlay BGR"};
  state.SetLabel(names[state.range(0)]);
}

// Encodes the input of the benchmark's argument with `encode` in a loop; reports the file size.
template <class Encode>
void encode_loop(benchmark::State& state, Encode encode) {
  const cv::Mat image = input(static_cast<int>(state.range(0)));
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::vector<std::uint8_t> file = encode(image);
    bytes = file.size();
    benchmark::DoNotOptimize(file.data());
  }
  state.counters["file_kB"] = static_cast<double>(bytes) / 1000.0;
  set_label(state);
}

void BM_EncodeFacet(benchmark::State& state) {
  encode_loop(state, [](const cv::Mat& image) { return png::encode(image); });
}

// The run coder, meant for label images.
void BM_EncodeFacetRuns(benchmark::State& state) {
  encode_loop(state, [](const cv::Mat& image) {
    return png::encode(image, {.deflate = png::Deflate::runs});
  });
}

void BM_EncodeOpenCV(benchmark::State& state) {
  encode_loop(state, [](const cv::Mat& image) {
    std::vector<std::uint8_t> file;
    cv::imencode(".png", image, file);
    return file;
  });
}

// Decoding is measured on files libpng wrote (through OpenCV: a filter chosen per row), as the
// bundled dataset's are.
void BM_DecodeFacet(benchmark::State& state) {
  const cv::Mat image = input(static_cast<int>(state.range(0)));
  std::vector<std::uint8_t> file;
  cv::imencode(".png", image, file);
  for (auto _ : state) {
    std::optional<cv::Mat> decoded = png::decode(file);
    benchmark::DoNotOptimize(decoded->data);
  }
  set_label(state);
}

void BM_DecodeOpenCV(benchmark::State& state) {
  const cv::Mat image = input(static_cast<int>(state.range(0)));
  std::vector<std::uint8_t> file;
  cv::imencode(".png", image, file);
  for (auto _ : state) {
    cv::Mat decoded = cv::imdecode(file, cv::IMREAD_UNCHANGED);
    benchmark::DoNotOptimize(decoded.data);
  }
  set_label(state);
}

BENCHMARK(BM_EncodeFacet)->DenseRange(kDepth, kOverlay)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EncodeFacetRuns)->DenseRange(kDepth, kOverlay)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EncodeOpenCV)->DenseRange(kDepth, kOverlay)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DecodeFacet)->DenseRange(kDepth, kOverlay)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DecodeOpenCV)->DenseRange(kDepth, kOverlay)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
