// The framework's own cost: what a stage call costs beyond the stage's work, and proof that a
// fan-out shares one image instead of copying it.
//
//   build/bin/facet_bench_framework --benchmark_repetitions=10
//   --benchmark_report_aggregates_only=true
//
// BM_PassThroughChain/N runs a source and N pass-through stages over 640x480 depth frames; the
// counter `per_stage_call` is (time per frame) / (N + 1); the framework's
// overhead per added stage is (per_frame(10) - per_frame(0)) / 10. BM_FanOut feeds one image to
// four consumers and counts distinct pixel buffers they saw beyond the first (`image_copies`, must
// be 0).

#include <benchmark/benchmark.h>

#include <set>

#include "facet/framework/executor.hpp"
#include "facet/framework/registry.hpp"
#include "facet/types/images.hpp"

namespace {

// A source that never ends: the same prepared 640x480 frame, re-stamped for each index.
class EndlessSource final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("bench.source", "Emits 640x480 depth frames forever.")
        .output<facet::DepthImage>("depth", "A 640x480 uint16 depth image.");
  }
  explicit EndlessSource(const facet::Params&) {
    image_.depth = cv::Mat(480, 640, CV_16UC1, cv::Scalar(1000));
  }
  void process(facet::ProcessContext& ctx) override {
    facet::DepthImage image = image_;  // shares the pixel buffer (cv::Mat is reference-counted)
    image.frame.index = ctx.frame_index();
    ctx.output("depth", std::move(image));
  }

 private:
  facet::DepthImage image_;
};

class PassThrough final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("bench.pass", "Forwards its input packet.")
        .input<facet::DepthImage>("depth", "Any depth image.")
        .output<facet::DepthImage>("depth", "The same packet.")
        .concurrency(facet::Concurrency::reentrant);
  }
  explicit PassThrough(const facet::Params&) {}
  void process(facet::ProcessContext& ctx) override {
    ctx.output_packet("depth", ctx.input_packet("depth"));
  }
};

// Collects the pixel buffers consumers saw during one frame.
std::set<const void*>& buffers_seen() {
  static std::set<const void*> buffers;
  return buffers;
}

class BufferProbe final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("bench.probe", "Records the pixel buffer it receives.")
        .input<facet::DepthImage>("depth", "Any depth image.");
  }
  explicit BufferProbe(const facet::Params&) {}
  void process(facet::ProcessContext& ctx) override {
    buffers_seen().insert(ctx.input<facet::DepthImage>("depth").depth.data);
  }
};

facet::Registry make_registry() {
  facet::Registry registry;
  registry.add<EndlessSource>();
  registry.add<PassThrough>();
  registry.add<BufferProbe>();
  return registry;
}

facet::ValidatedNode make_node(const facet::Registry& registry, std::string id,
                               const std::string& stage, std::optional<std::size_t> from) {
  facet::ValidatedNode node;
  node.id = std::move(id);
  node.stage = registry.find(stage);
  node.params = node.stage->spec.default_params();
  if (from) node.inputs.push_back(facet::Connection{*from, 0});
  return node;
}

constexpr std::int64_t kFramesPerIteration = 1000;

void BM_PassThroughChain(benchmark::State& state) {
  const auto registry = make_registry();
  const auto stages = static_cast<std::size_t>(state.range(0));
  facet::ValidatedGraph graph;
  graph.name = "chain";
  graph.nodes.push_back(make_node(registry, "source", "bench.source", std::nullopt));
  for (std::size_t i = 0; i < stages; ++i) {
    graph.nodes.push_back(make_node(registry, "pass" + std::to_string(i), "bench.pass", i));
  }
  facet::SequentialExecutor executor(graph);
  facet::RunOptions options;
  options.max_frames = kFramesPerIteration;
  for (auto _ : state) {
    const auto stats = executor.run(options);
    benchmark::DoNotOptimize(stats.frames);
  }
  const double frames = static_cast<double>(state.iterations() * kFramesPerIteration);
  // Inverted rates: seconds per frame and per stage call (the source counts as a call).
  state.counters["per_frame"] =
      benchmark::Counter(frames, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["per_stage_call"] =
      benchmark::Counter(frames * static_cast<double>(stages + 1),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PassThroughChain)->Arg(0)->Arg(10)->Unit(benchmark::kMicrosecond);

void BM_FanOut(benchmark::State& state) {
  const auto registry = make_registry();
  facet::ValidatedGraph graph;
  graph.name = "fan-out";
  graph.nodes.push_back(make_node(registry, "source", "bench.source", std::nullopt));
  for (int i = 0; i < 4; ++i) {
    graph.nodes.push_back(make_node(registry, "probe" + std::to_string(i), "bench.probe", 0));
  }
  facet::SequentialExecutor executor(graph);
  facet::RunOptions options;
  options.max_frames = 1;
  std::size_t copies = 0;
  for (auto _ : state) {
    buffers_seen().clear();
    executor.run(options);
    copies += buffers_seen().size() - 1;  // every consumer saw the same buffer: 0 copies
  }
  state.counters["image_copies"] = static_cast<double>(copies);
}
BENCHMARK(BM_FanOut)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
