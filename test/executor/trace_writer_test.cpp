#include "facet/framework/trace_writer.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>  // JSON is YAML: the trace is read back by a parser, not by searching

#include <map>
#include <set>
#include <sstream>

#include "facet/framework/executor.hpp"
#include "facet/framework/pipelined_executor.hpp"
#include "pipeline_test_stages.hpp"
#include "test_graph.hpp"

namespace {

facet::ValidatedGraph chain(const facet::Registry& registry, std::int64_t frames) {
  return facet::test::make_graph(registry, {{"source", "ptest.source", {{"frames", frames}}, {}},
                                            {"serial", "ptest.serial", {}, {"source"}},
                                            {"clone", "ptest.clonable", {}, {"serial"}},
                                            {"sink", "ptest.sink", {}, {"clone"}}});
}

// The trace of a run: per (node, frame), how many slices, and the threads seen.
struct ParsedTrace {
  std::map<std::pair<std::string, std::int64_t>, int> slices;
  std::map<std::int64_t, std::string> thread_names;
  std::set<std::int64_t> threads_with_slices;
};

ParsedTrace parse(const std::string& text) {
  ParsedTrace trace;
  const YAML::Node root = YAML::Load(text);
  EXPECT_EQ(root["displayTimeUnit"].as<std::string>(), "ms");
  for (const auto& event : root["traceEvents"]) {
    const auto phase = event["ph"].as<std::string>();
    EXPECT_EQ(event["pid"].as<std::int64_t>(), 1);
    if (phase == "M") {
      if (event["name"].as<std::string>() == "thread_name") {
        trace.thread_names[event["tid"].as<std::int64_t>()] =
            event["args"]["name"].as<std::string>();
      }
      continue;
    }
    EXPECT_EQ(phase, "X");
    EXPECT_GE(event["ts"].as<std::int64_t>(), 0);
    EXPECT_GE(event["dur"].as<std::int64_t>(), 0);
    EXPECT_FALSE(event["args"]["stage"].as<std::string>().empty());
    ++trace.slices[{event["name"].as<std::string>(), event["args"]["frame"].as<std::int64_t>()}];
    trace.threads_with_slices.insert(event["tid"].as<std::int64_t>());
  }
  return trace;
}

TEST(TraceWriter, OneSlicePerStagePerFrameFromBothExecutors) {
  facet::Registry registry;
  facet::test::add_pipeline_test_stages(registry);
  const auto g = chain(registry, 6);
  for (const bool pipelined : {false, true}) {
    facet::test::pipeline_probe().reset();
    facet::RunOptions options;
    options.record_calls = true;
    facet::RunStats stats;
    if (pipelined) {
      stats = facet::PipelinedExecutor(g, {2, 3}).run(options);
    } else {
      stats = facet::SequentialExecutor(g).run(options);
    }
    std::ostringstream out;
    facet::write_chrome_trace(out, stats, g.name);
    const ParsedTrace trace = parse(out.str());
    for (const char* node : {"source", "serial", "clone", "sink"}) {
      for (std::int64_t frame = 0; frame < 6; ++frame)
        EXPECT_EQ((trace.slices.count({node, frame}) != 0 ? trace.slices.at({node, frame}) : 0), 1)
            << node << " frame " << frame << (pipelined ? " pipelined" : " sequential");
    }
    // The source's last call, which ended the stream, is a slice too; nothing else is.
    EXPECT_EQ(trace.slices.size(), 4u * 6u + 1u);
    EXPECT_EQ(trace.slices.count({"source", 6}), 1u);
    // Every thread that ran a stage is named.
    for (const auto thread : trace.threads_with_slices) {
      EXPECT_EQ(trace.thread_names.count(thread), 1u) << thread;
      EXPECT_LT(thread, pipelined ? 2 : 1);
    }
  }
}

}  // namespace
