#include "facet/framework/pipelined_executor.hpp"

#include <gtest/gtest.h>

#include <map>
#include <numeric>

#include "facet/framework/executor.hpp"
#include "facet/framework/registry.hpp"
#include "pipeline_test_stages.hpp"
#include "test_graph.hpp"

namespace {

using facet::test::pipeline_probe;

using facet::test::NodeDesc;

class PipelinedExecutorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    pipeline_probe().reset();
    facet::test::add_pipeline_test_stages(registry_);
  }

  facet::ValidatedGraph graph(const std::vector<NodeDesc>& nodes) {
    return facet::test::make_graph(registry_, nodes);
  }

  // source → serial → clonable → reentrant → sink, with `frames` frames.
  facet::ValidatedGraph chain(std::int64_t frames, std::int64_t gap_every = 0) {
    return graph({{"source", "ptest.source", {{"frames", frames}, {"gap_every", gap_every}}, {}},
                  {"serial", "ptest.serial", {}, {"source"}},
                  {"clone", "ptest.clonable", {}, {"serial"}},
                  {"shared", "ptest.reentrant", {}, {"clone"}},
                  {"sink", "ptest.sink", {}, {"shared"}}});
  }

  static std::vector<std::int64_t> frames_of(const std::string& node) {
    const std::lock_guard lock(pipeline_probe().mutex);
    return pipeline_probe().frames[node];
  }
  static std::vector<std::int64_t> iota(std::int64_t n) {
    std::vector<std::int64_t> out(static_cast<std::size_t>(n));
    std::iota(out.begin(), out.end(), 0);
    return out;
  }

  facet::Registry registry_;
};

TEST_F(PipelinedExecutorTest, SerialStagesAndSinksSeeEveryFrameInOrderOneAtATime) {
  const auto g = chain(40);
  facet::PipelinedExecutor executor(g, {4, 6});
  std::vector<std::int64_t> reported;
  std::int64_t stream_frames = -1;
  facet::RunOptions options;
  options.on_frame = [&](const facet::FrameEvent& e) {
    reported.push_back(e.index);
    stream_frames = e.stream_frames;
  };
  const auto stats = executor.run(options);
  EXPECT_EQ(stats.frames, 40);
  EXPECT_EQ(stream_frames, 40);  // the source's own count
  EXPECT_EQ(frames_of("source"), iota(40));
  EXPECT_EQ(frames_of("serial"), iota(40));
  EXPECT_EQ(frames_of("sink"), iota(40));
  EXPECT_EQ(reported, iota(40));
  EXPECT_TRUE(pipeline_probe().overlaps.empty()) << pipeline_probe().overlaps.front();
  EXPECT_EQ(pipeline_probe().most_at_once["serial"], 1);
  EXPECT_EQ(pipeline_probe().most_at_once["sink"], 1);
  // Every node ran once per frame, the source once more to end the stream, as in the
  // sequential run.
  for (const auto& node : stats.nodes)
    EXPECT_EQ(node.call_ms.size(), node.id == "source" ? 41u : 40u) << node.id;
  EXPECT_EQ(stats.frame_ms.size(), 40u);
  EXPECT_GT(stats.throughput_fps(), 0.0);
}

TEST_F(PipelinedExecutorTest, ClonableStagesGetOneInstancePerThreadOthersOne) {
  const auto g = chain(4);
  facet::PipelinedExecutor executor(g, {3, 8});
  EXPECT_EQ(executor.threads(), 3);
  EXPECT_EQ(executor.in_flight(), 8);
  EXPECT_EQ(executor.instances(0), 1u);  // serial source
  EXPECT_EQ(executor.instances(1), 1u);  // serial
  EXPECT_EQ(executor.instances(2), 3u);  // clonable
  EXPECT_EQ(executor.instances(3), 1u);  // reentrant
  EXPECT_EQ(pipeline_probe().instances["ptest.clonable"], 3);
  EXPECT_EQ(pipeline_probe().instances["ptest.reentrant"], 1);
  executor.run();
  // Each instance is opened and closed once.
  const auto& events = pipeline_probe().events;
  EXPECT_EQ(std::count(events.begin(), events.end(), "open clone"), 3);
  EXPECT_EQ(std::count(events.begin(), events.end(), "close ptest.clonable"), 3);
}

TEST_F(PipelinedExecutorTest, NoMoreClonesThanFramesInFlight) {
  const auto g = chain(4);
  facet::PipelinedExecutor executor(g, {4, 2});
  EXPECT_EQ(executor.instances(2), 2u);
}

TEST_F(PipelinedExecutorTest, FramesInFlightAreBounded) {
  // The serial stage sees frame f only after the sink has finished frame f - in_flight at the
  // latest: the source cannot run further ahead than the pipeline holds.
  const auto g = chain(30);
  facet::PipelinedExecutor executor(g, {4, 3});
  executor.run();
  EXPECT_EQ(frames_of("sink"), iota(30));
  EXPECT_LE(pipeline_probe().most_at_once["shared"], 3);
  EXPECT_LE(pipeline_probe().most_at_once["clone"], 3);
}

TEST_F(PipelinedExecutorTest, EmptyOutputSkipsConsumersAsTheSequentialExecutorDoes) {
  const auto g = chain(12, 3);
  facet::SequentialExecutor sequential(g);
  const auto expected = sequential.run();
  pipeline_probe().reset();
  facet::PipelinedExecutor executor(g, {3, 4});
  const auto stats = executor.run();
  ASSERT_EQ(stats.nodes.size(), expected.nodes.size());
  EXPECT_EQ(stats.frames, expected.frames);
  for (std::size_t n = 0; n < stats.nodes.size(); ++n) {
    EXPECT_EQ(stats.nodes[n].skipped, expected.nodes[n].skipped) << stats.nodes[n].id;
    EXPECT_EQ(stats.nodes[n].call_ms.size(), expected.nodes[n].call_ms.size());
  }
  EXPECT_EQ(stats.nodes[4].skipped, 4);
  EXPECT_EQ(frames_of("sink"), (std::vector<std::int64_t>{0, 1, 3, 4, 6, 7, 9, 10}));
}

TEST_F(PipelinedExecutorTest, AFailureStopsTheRunNamesNodeAndFrameAndClosesEverything) {
  for (const char* failing : {"ptest.serial", "ptest.clonable", "ptest.reentrant"}) {
    pipeline_probe().reset();
    auto g = graph({{"source", "ptest.source", {{"frames", std::int64_t{1000}}}, {}},
                    {"work", failing, {{"fail_at", std::int64_t{5}}}, {"source"}},
                    {"sink", "ptest.sink", {}, {"work"}}});
    facet::PipelinedExecutor executor(g, {3, 4});
    try {
      executor.run();
      ADD_FAILURE() << "expected a RunError from " << failing;
    } catch (const facet::RunError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("node 'work' (" + std::string(failing) + ")"), std::string::npos)
          << message;
      EXPECT_NE(message.find("frame 5 (f5)"), std::string::npos) << message;
      EXPECT_NE(message.find("deliberate failure"), std::string::npos) << message;
    }
    // The run stopped soon after the failure rather than running the stream to its end, and the
    // sink never saw the failed frame or one after it out of order.
    const auto sink = frames_of("sink");
    EXPECT_LT(frames_of("source").size(), 20u) << failing;
    EXPECT_EQ(sink, iota(static_cast<std::int64_t>(sink.size())));
    EXPECT_LE(sink.size(), 5u);
    const auto& events = pipeline_probe().events;
    const auto opens = std::count_if(events.begin(), events.end(),
                                     [](const std::string& e) { return e.rfind("open", 0) == 0; });
    const auto closes = std::count_if(events.begin(), events.end(), [](const std::string& e) {
      return e.rfind("close", 0) == 0;
    });
    EXPECT_EQ(opens, closes) << failing;
    EXPECT_EQ(events.back(), "close source") << failing;
  }
}

TEST_F(PipelinedExecutorTest, ASourceEndingAtOnceOrEarlyEndsTheRun) {
  for (const std::int64_t frames : {0, 1, 2, 5}) {
    pipeline_probe().reset();
    const auto g = chain(frames);
    facet::PipelinedExecutor executor(g, {4, 8});
    const auto stats = executor.run();
    EXPECT_EQ(stats.frames, frames);
    EXPECT_EQ(frames_of("sink"), iota(frames));
  }
}

TEST_F(PipelinedExecutorTest, StopsAtMaxFrames) {
  const auto g = chain(100);
  facet::PipelinedExecutor executor(g, {2, 4});
  facet::RunOptions options;
  options.max_frames = 7;
  EXPECT_EQ(executor.run(options).frames, 7);
  EXPECT_EQ(frames_of("sink"), iota(7));
  EXPECT_EQ(frames_of("source"), iota(7));
}

TEST_F(PipelinedExecutorTest, BlockSourceDropsNothing) {
  auto g = graph({{"source", "ptest.source", {{"frames", std::int64_t{10}}}, {}},
                  {"sink", "ptest.sink", {{"hold_until_calls", std::int64_t{1}}}, {"source"}}});
  facet::PipelinedExecutor executor(g, {2, 1});
  const auto stats = executor.run();
  EXPECT_EQ(stats.dropped, 0);
  EXPECT_EQ(frames_of("sink"), iota(10));
}

TEST_F(PipelinedExecutorTest, LatestSourceReplacesStaleFramesAndCountsThem) {
  // One frame in flight. The sink holds frame 0 until the source has been called 6 times: the
  // source reads frames 1..5 meanwhile, each replacing the one waiting before it (1, 2, 3 are
  // dropped; 4 waits, 5 is being read when the sink lets go... or has been read and replaced 4).
  auto g = graph({{"source", "ptest.source", {{"frames", std::int64_t{8}}}, {}},
                  {"sink", "ptest.sink", {{"hold_until_calls", std::int64_t{6}}}, {"source"}}});
  facet::PipelinedExecutor executor(g, {2, 1});
  facet::RunOptions options;
  options.source_policy = facet::SourcePolicy::latest;
  const auto stats = executor.run(options);
  const auto sink = frames_of("sink");
  ASSERT_FALSE(sink.empty());
  EXPECT_EQ(sink.front(), 0);
  EXPECT_TRUE(std::is_sorted(sink.begin(), sink.end()));
  // Every frame the source read was either processed or counted as dropped.
  EXPECT_EQ(static_cast<std::int64_t>(sink.size()) + stats.dropped, 8);
  EXPECT_EQ(stats.frames, static_cast<std::int64_t>(sink.size()));
  EXPECT_GE(stats.dropped, 3);
  EXPECT_EQ(sink.back(), 7);  // the newest frame is never the one dropped
}

TEST_F(PipelinedExecutorTest, RecordsOneCallPerStagePerFrame) {
  const auto g = chain(6);
  facet::PipelinedExecutor executor(g, {2, 3});
  facet::RunOptions options;
  options.record_calls = true;
  const auto stats = executor.run(options);
  std::map<std::pair<std::size_t, std::int64_t>, int> calls;
  for (const auto& call : stats.calls) {
    ++calls[{call.node, call.frame}];
    EXPECT_GE(call.thread, 0);
    EXPECT_LT(call.thread, 2);
    EXPECT_GE(call.duration_ms, 0.0);
  }
  // Five nodes, six frames, plus the source's call that ended the stream.
  EXPECT_EQ(stats.calls.size(), 5u * 6u + 1u);
  for (std::size_t node = 0; node < 5; ++node) {
    for (std::int64_t frame = 0; frame < 6; ++frame)
      EXPECT_EQ((calls[{node, frame}]), 1) << node << " " << frame;
  }
}

TEST_F(PipelinedExecutorTest, AStalledCallIsReportedWithNodeAndFrame) {
  facet::test::OrderedSink::stall_released = false;
  auto g = graph({{"source", "ptest.source", {{"frames", std::int64_t{4}}}, {}},
                  {"sink", "ptest.sink", {{"stall_at", std::int64_t{2}}}, {"source"}}});
  for (const bool pipelined : {false, true}) {
    pipeline_probe().reset();
    {
      const std::lock_guard lock(pipeline_probe().mutex);
      facet::test::OrderedSink::stall_released = false;
    }
    std::vector<facet::StallReport> reports;
    facet::RunOptions options;
    options.stall_after = std::chrono::milliseconds(20);
    options.on_stall = [&](const facet::StallReport& report) {
      auto& probe = pipeline_probe();
      const std::lock_guard lock(probe.mutex);
      reports.push_back(report);
      facet::test::OrderedSink::stall_released = true;
      probe.changed.notify_all();
    };
    facet::RunStats stats;
    if (pipelined) {
      facet::PipelinedExecutor executor(g, {2, 2});
      stats = executor.run(options);
    } else {
      facet::SequentialExecutor executor(g);
      stats = executor.run(options);
    }
    EXPECT_EQ(stats.frames, 4);
    ASSERT_EQ(reports.size(), 1u) << (pipelined ? "pipelined" : "sequential");
    EXPECT_EQ(reports[0].node, "sink");
    EXPECT_EQ(reports[0].frame, 2);
    EXPECT_GE(reports[0].held_ms, 20.0);
    EXPECT_NE(reports[0].message.find("node 'sink' (ptest.sink) has held frame 2"),
              std::string::npos)
        << reports[0].message;
  }
}

}  // namespace

// --- parallelism inside a stage call (ProcessContext::parallel_for) ---

TEST_F(PipelinedExecutorTest, StagesBorrowIdleWorkersForTheirParallelFor) {
  const auto g = graph({{"source", "ptest.source", {{"frames", std::int64_t{3}}}, {}},
                        {"parallel", "ptest.parallel", {{"wait_for_help", true}}, {"source"}},
                        {"sink", "ptest.sink", {}, {"parallel"}}});
  facet::PipelinedExecutor executor(g, {2, 1});  // one frame at a time: the second thread is idle
  const auto stats = executor.run({});
  EXPECT_EQ(stats.frames, 3);
  const std::lock_guard lock(pipeline_probe().mutex);
  EXPECT_EQ(pipeline_probe().parallelism, 2);
  EXPECT_TRUE(pipeline_probe().helped) << "no piece ran on the idle worker";
  EXPECT_TRUE(pipeline_probe().overlaps.empty()) << pipeline_probe().overlaps.front();
}

TEST_F(PipelinedExecutorTest, ParallelForCoversEveryItemOnceWhileOtherFramesRun) {
  // Four threads, frames in flight: the pieces run on whoever is free, in any order.
  const auto g = graph({{"source", "ptest.source", {{"frames", std::int64_t{30}}}, {}},
                        {"clone", "ptest.clonable", {{"work_us", std::int64_t{300}}}, {"source"}},
                        {"parallel", "ptest.parallel", {{"items", std::int64_t{97}}}, {"clone"}},
                        {"sink", "ptest.sink", {}, {"parallel"}}});
  facet::PipelinedExecutor executor(g, {4, 6});
  EXPECT_EQ(executor.run({}).frames, 30);
  EXPECT_EQ(frames_of("sink"), iota(30));
  const std::lock_guard lock(pipeline_probe().mutex);
  EXPECT_EQ(pipeline_probe().parallelism, 4);
  EXPECT_TRUE(pipeline_probe().overlaps.empty()) << pipeline_probe().overlaps.front();
}

TEST_F(PipelinedExecutorTest, AFailingPieceFailsTheRunWithItsMessage) {
  const auto g =
      graph({{"source", "ptest.source", {{"frames", std::int64_t{5}}}, {}},
             {"parallel", "ptest.parallel", {{"fail_item", std::int64_t{40}}}, {"source"}},
             {"sink", "ptest.sink", {}, {"parallel"}}});
  facet::PipelinedExecutor executor(g, {2, 2});
  try {
    executor.run({});
    ADD_FAILURE() << "the run went through a failing piece";
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find("deliberate failure in item 40"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("parallel"), std::string::npos) << error.what();
  }
}

TEST_F(PipelinedExecutorTest, OneThreadRunsParallelForInline) {
  const auto g = graph({{"source", "ptest.source", {{"frames", std::int64_t{2}}}, {}},
                        {"parallel", "ptest.parallel", {}, {"source"}},
                        {"sink", "ptest.sink", {}, {"parallel"}}});
  facet::PipelinedExecutor executor(g, {1, 1});
  EXPECT_EQ(executor.run({}).frames, 2);
  const std::lock_guard lock(pipeline_probe().mutex);
  EXPECT_EQ(pipeline_probe().parallelism, 1);
  EXPECT_FALSE(pipeline_probe().helped);
  EXPECT_TRUE(pipeline_probe().overlaps.empty()) << pipeline_probe().overlaps.front();
}
