// Unit tests of the template's stages with facet::testing::StageRunner: one stage, no graph.
// Plain asserts keep the template free of test-framework dependencies; GoogleTest works the same.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <facet/testing/stage_runner.hpp>
#include <facet/types/images.hpp>

#include "../src/counter_source.hpp"
#include "../src/depth_threshold.hpp"

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "FAILED: %s\n", what);
    ++failures;
  }
}

void counter_emits_frames_then_ends() {
  facet::testing::StageRunner<facet_template::CounterSource> runner(
      {{"frames", std::int64_t{2}}, {"width", std::int64_t{5}}, {"height", std::int64_t{3}}});
  runner.run();
  const auto& first = runner.output<facet::DepthImage>("depth");
  check(first.depth.rows == 3 && first.depth.cols == 5, "counter: image size follows params");
  check(first.depth.at<std::uint16_t>(0, 0) == 500, "counter: left column at `near`");
  check(first.depth.at<std::uint16_t>(2, 4) == 2000, "counter: right column at `far`");
  check(!runner.at_end_of_stream(), "counter: not at end after the first frame");
  runner.run();
  check(runner.output<facet::DepthImage>("depth").frame.index == 1, "counter: frame index");
  runner.run();
  check(runner.at_end_of_stream(), "counter: ends the stream after `frames` images");
}

void threshold_drops_far_pixels_and_reports_ratio() {
  facet::DepthImage depth;
  depth.depth = (cv::Mat_<std::uint16_t>(1, 4) << 0, 800, 1200, 1600);
  facet::testing::StageRunner<facet_template::DepthThreshold> runner(
      {{"max_mm", std::int64_t{1000}}});
  runner.set_input("depth", facet::Packet::make(depth));
  runner.run();
  const auto& out = runner.output<facet::DepthImage>("depth").depth;
  check(out.at<std::uint16_t>(0, 1) == 800, "threshold: keeps near pixels");
  check(out.at<std::uint16_t>(0, 2) == 0 && out.at<std::uint16_t>(0, 3) == 0,
        "threshold: zeroes far pixels");
  check(depth.depth.at<std::uint16_t>(0, 3) == 1600, "threshold: leaves its input unchanged");
  check(runner.metrics().size() == 1 && runner.metrics()[0].name == "kept_ratio" &&
            runner.metrics()[0].value == 1.0 / 3.0,
        "threshold: kept_ratio counts measured pixels only");
}

void threshold_rejects_metres() {
  facet::DepthImage depth;
  depth.depth = cv::Mat(2, 2, CV_32FC1, cv::Scalar(1.0));
  facet::testing::StageRunner<facet_template::DepthThreshold> runner;
  runner.set_input("depth", facet::Packet::make(depth));
  bool threw = false;
  try {
    runner.run();
  } catch (const facet::StageError&) {
    threw = true;
  }
  check(threw, "threshold: StageError for depth in metres");
}

}  // namespace

int main() {
  counter_emits_frames_then_ends();
  threshold_drops_far_pixels_and_reports_ratio();
  threshold_rejects_metres();
  if (failures == 0) std::puts("all template stage tests passed");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
