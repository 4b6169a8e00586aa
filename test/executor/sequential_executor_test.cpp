#include <gtest/gtest.h>

#include <map>

#include "facet/framework/executor.hpp"
#include "facet/framework/registry.hpp"
#include "facet/types/images.hpp"
#include "test_graph.hpp"

namespace {

// What the test stages saw; reset by each test. Stages only see their Params, so tests observe
// them through this probe.
struct Probe {
  std::vector<std::string> events;                       // "open id", "close id"
  std::map<std::string, std::vector<const void*>> seen;  // node id → payload addresses
};
Probe& probe() {
  static Probe instance;
  return instance;
}

class Counter final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("test.counter", "Emits `frames` small depth images, then ends.")
        .output<facet::DepthImage>("depth", "A 4x4 image whose pixels hold the frame index + 1.")
        .param("frames", 3, "Frames to emit.", {.min = 0})
        .param("gap_every", 0, "Leave the output empty every n-th frame (0 = never).", {.min = 0});
  }
  explicit Counter(const facet::Params& p)
      : frames_(p.get_int("frames")), gap_every_(p.get_int("gap_every")) {}
  void open(const facet::OpenContext& ctx) override {
    probe().events.push_back("open " + ctx.node_id);
  }
  void close() override { probe().events.push_back("close counter"); }
  void process(facet::ProcessContext& ctx) override {
    if (ctx.frame_index() >= frames_) {
      ctx.end_of_stream();
      return;
    }
    ctx.metric("index", static_cast<double>(ctx.frame_index()));
    facet::test::emit_counting_frame(ctx, gap_every_, frames_);
  }

 private:
  std::int64_t frames_;
  std::int64_t gap_every_;
};

class Record final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("test.record", "Records the payload address it receives.")
        .input<facet::DepthImage>("depth", "Anything.")
        .param("fail_at", -1, "Throw a StageError at this frame (-1 = never).", {.min = -1});
  }
  explicit Record(const facet::Params& p) : fail_at_(p.get_int("fail_at")) {}
  void open(const facet::OpenContext& ctx) override {
    id_ = ctx.node_id;
    probe().events.push_back("open " + id_);
  }
  void close() override { probe().events.push_back("close " + id_); }
  void process(facet::ProcessContext& ctx) override {
    if (ctx.frame_index() == fail_at_) throw facet::StageError("deliberate failure");
    probe().seen[ctx.node_id()].push_back(ctx.input_packet("depth").address());
  }

 private:
  std::int64_t fail_at_;
  std::string id_;
};

class Unbuildable final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("test.unbuildable", "Its constructor always fails.")
        .input<facet::DepthImage>("depth", "Anything.");
  }
  explicit Unbuildable(const facet::Params&) { throw facet::StageError("cannot open device"); }
  void process(facet::ProcessContext&) override {}
};

using facet::test::NodeDesc;

class SequentialExecutorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    probe() = {};
    registry_.add<Counter>();
    registry_.add<Record>();
    registry_.add<Unbuildable>();
  }

  facet::ValidatedGraph graph(const std::vector<NodeDesc>& nodes) {
    return facet::test::make_graph(registry_, nodes);
  }

  facet::Registry registry_;
};

TEST_F(SequentialExecutorTest, RunsUntilTheSourceEndsTheStream) {
  const auto g = graph({{"counter", "test.counter", {{"frames", std::int64_t{5}}}, {}},
                        {"sink", "test.record", {}, {"counter"}}});
  facet::SequentialExecutor executor(g);
  const auto stats = executor.run();
  EXPECT_EQ(stats.frames, 5);
  EXPECT_EQ(stats.frame_ms.size(), 5u);
  ASSERT_EQ(stats.nodes.size(), 2u);
  EXPECT_EQ(stats.nodes[1].call_ms.size(), 5u);
  EXPECT_EQ(probe().seen["sink"].size(), 5u);
  EXPECT_EQ(stats.nodes[0].metrics.at("index").size(), 5u);
  EXPECT_DOUBLE_EQ(stats.nodes[0].metrics.at("index").back(), 4.0);
}

TEST_F(SequentialExecutorTest, StopsAtMaxFrames) {
  const auto g = graph({{"counter", "test.counter", {{"frames", std::int64_t{100}}}, {}},
                        {"sink", "test.record", {}, {"counter"}}});
  facet::SequentialExecutor executor(g);
  facet::RunOptions options;
  options.max_frames = 7;
  std::vector<std::string> stems;
  std::vector<std::int64_t> stream_frames;
  options.on_frame = [&](const facet::FrameEvent& e) {
    stems.push_back(e.stem);
    stream_frames.push_back(e.stream_frames);
  };
  EXPECT_EQ(executor.run(options).frames, 7);
  ASSERT_EQ(stems.size(), 7u);
  EXPECT_EQ(stems.front(), "f0");
  EXPECT_EQ(stems.back(), "f6");
  // The source's own count comes with every frame; the progress display cuts it to the limit.
  EXPECT_EQ(stream_frames, std::vector<std::int64_t>(7, 100));
}

// Per-frame bookkeeping only when asked: a long live run does not grow by it.
TEST_F(SequentialExecutorTest, RecordsWhichFrameEachValueBelongsToOnlyWhenAsked) {
  const auto g = graph({{"counter", "test.counter", {{"gap_every", std::int64_t{2}}}, {}},
                        {"sink", "test.record", {}, {"counter"}}});
  facet::RunOptions options;
  options.record_frames = true;
  const auto stats = facet::SequentialExecutor(g).run(options);
  EXPECT_EQ(stats.frame_indices, (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(stats.frame_stems, (std::vector<std::string>{"f0", "", "f2"}));
  // The sink was skipped in frame 1 (its input was empty): its times are of frames 0 and 2.
  EXPECT_EQ(stats.nodes[1].call_frames, (std::vector<std::int64_t>{0, 2}));
  EXPECT_EQ(stats.nodes[0].metric_frames.at("index"), (std::vector<std::int64_t>{0, 1, 2}));

  const auto plain = facet::SequentialExecutor(g).run();
  EXPECT_EQ(plain.frames, 3);
  EXPECT_TRUE(plain.frame_indices.empty());
  EXPECT_TRUE(plain.nodes[1].call_frames.empty());
  EXPECT_TRUE(plain.nodes[0].metric_frames.empty());
}

TEST_F(SequentialExecutorTest, FanOutSharesOnePayloadAmongAllConsumers) {
  const auto g = graph({{"counter", "test.counter", {}, {}},
                        {"a", "test.record", {}, {"counter"}},
                        {"b", "test.record", {}, {"counter"}},
                        {"c", "test.record", {}, {"counter"}},
                        {"d", "test.record", {}, {"counter"}}});
  facet::SequentialExecutor executor(g);
  EXPECT_EQ(executor.run().frames, 3);
  for (std::size_t frame = 0; frame < 3; ++frame) {
    const void* first = probe().seen["a"].at(frame);
    EXPECT_NE(first, nullptr);
    for (const char* id : {"b", "c", "d"})
      EXPECT_EQ(probe().seen[id].at(frame), first) << id;
  }
}

TEST_F(SequentialExecutorTest, EmptyOutputSkipsConsumersWithARequiredInput) {
  const auto g = graph({{"counter",
                         "test.counter",
                         {{"frames", std::int64_t{6}}, {"gap_every", std::int64_t{2}}},
                         {}},
                        {"sink", "test.record", {}, {"counter"}}});
  facet::SequentialExecutor executor(g);
  const auto stats = executor.run();
  EXPECT_EQ(stats.frames, 6);
  EXPECT_EQ(stats.nodes[1].skipped, 3);
  EXPECT_EQ(stats.nodes[1].call_ms.size(), 3u);
}

TEST_F(SequentialExecutorTest, StageFailureNamesNodeStageAndFrameAndClosesEverything) {
  const auto g = graph({{"counter", "test.counter", {}, {}},
                        {"sink", "test.record", {{"fail_at", std::int64_t{1}}}, {"counter"}}});
  facet::SequentialExecutor executor(g);
  try {
    executor.run();
    FAIL() << "expected a RunError";
  } catch (const facet::RunError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("node 'sink' (test.record)"), std::string::npos) << message;
    EXPECT_NE(message.find("frame 1 (f1)"), std::string::npos) << message;
    EXPECT_NE(message.find("deliberate failure"), std::string::npos) << message;
  }
  const std::vector<std::string> expected{"open counter", "open sink", "close sink",
                                          "close counter"};
  EXPECT_EQ(probe().events, expected);
}

TEST_F(SequentialExecutorTest, ConstructorFailureNamesTheNode) {
  const auto g =
      graph({{"counter", "test.counter", {}, {}}, {"device", "test.unbuildable", {}, {"counter"}}});
  try {
    facet::SequentialExecutor executor(g);
    FAIL() << "expected a RunError";
  } catch (const facet::RunError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("node 'device' (test.unbuildable)"), std::string::npos) << message;
    EXPECT_NE(message.find("cannot open device"), std::string::npos) << message;
  }
}

TEST_F(SequentialExecutorTest, AGraphWithoutSourceNeedsAFrameCount) {
  const auto g = graph({{"sink", "test.record", {}, {}}});
  facet::SequentialExecutor executor(g);
  EXPECT_THROW(executor.run(), facet::RunError);
}

}  // namespace
