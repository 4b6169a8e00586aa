// facet::Pipeline runs graphs/tabletop.yaml inside a program: the labels and objects it returns
// for the bundled frames are the very ones `facet run` writes to files.

#include "facet/pipeline.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <thread>

#include "bundled_frames.hpp"
#include "cli_runner.hpp"
#include "facet/types/geometry.hpp"
#include "io/objects_sink.hpp"

namespace facet::test {
namespace {

const std::filesystem::path kTabletop = source_dir() / "graphs/tabletop.yaml";
const std::filesystem::path kMosd = source_dir() / "data/mosd";
const std::vector<std::string> kStems = {"learn0",  "learn18", "learn20",
                                         "learn27", "learn36", "learn5"};

Packet depth_packet(const std::string& stem) {
  return Packet::make(bundled_mosd_frame(kMosd, stem));
}

// The labels as io.labels writes them: 16-bit ids.
cv::Mat as_written(const cv::Mat& labels) {
  cv::Mat out;
  labels.convertTo(out, CV_16UC1);
  return out;
}

bool same_image(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::countNonZero(a != b) == 0;
}

TEST(Pipeline, TabletopDeclaresItsInputsAndOutputs) {
  Pipeline pipeline(kTabletop);
  ASSERT_EQ(pipeline.inputs().size(), 1u);
  EXPECT_EQ(pipeline.inputs()[0].name, "depth");
  EXPECT_EQ(pipeline.inputs()[0].type_key, "facet.DepthImage/1");
  std::vector<std::string> outputs;
  for (const auto& port : pipeline.outputs())
    outputs.push_back(port.name);
  EXPECT_EQ(outputs, (std::vector<std::string>{"labels", "objects", "planes"}));
  // The source and the file sinks do not run: the host feeds the depth and reads the outputs.
  const auto nodes = pipeline.nodes();
  for (const char* absent : {"source", "labels_out", "objects_out", "overlay_out"}) {
    EXPECT_EQ(std::count(nodes.begin(), nodes.end(), absent), 0) << absent;
  }
  EXPECT_EQ(std::count(nodes.begin(), nodes.end(), "shapes"), 1);
}

TEST(Pipeline, LabelsAndObjectsEqualWhatTheCliWritesForEveryBundledFrame) {
  TempDir out("facet-pipeline-cli");
  const auto cli = run_cli("run " + shell_quote(kTabletop.string()) +
                           " --param output=" + shell_quote(out.path().string()));
  ASSERT_EQ(cli.exit_code, 0) << cli.out;

  Pipeline pipeline(kTabletop);
  for (std::size_t i = 0; i < kStems.size(); ++i) {
    const std::string& stem = kStems[i];
    auto depth = bundled_mosd_frame(kMosd, stem);
    depth.frame.index = static_cast<std::int64_t>(i);
    const FrameResult result = pipeline.process({{"depth", Packet::make(depth)}});
    const auto* labels = result.outputs.at("labels").get_if<LabelImage>();
    ASSERT_NE(labels, nullptr) << stem;
    const cv::Mat written =
        cv::imread((out.path() / "labels" / (stem + ".png")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(written.empty()) << stem;
    EXPECT_TRUE(same_image(as_written(labels->labels), written)) << stem;
    EXPECT_GE(labels->count, 1) << stem;

    const auto* objects = result.outputs.at("objects").get_if<ObjectList>();
    ASSERT_NE(objects, nullptr) << stem;
    // Frame index and timestamp come from the source in the CLI's run: compare the objects.
    const std::string json = io::objects_to_json(*objects);
    const std::string file = read_file(out.path() / "objects" / (stem + ".json"));
    EXPECT_EQ(json.substr(json.find("\"objects\"")), file.substr(file.find("\"objects\""))) << stem;
    EXPECT_NE(result.outputs.at("planes").get_if<SupportPlanes>(), nullptr);
    EXPECT_FALSE(result.timings.empty());
    EXPECT_EQ(result.frame_index, static_cast<std::int64_t>(i));
  }
}

TEST(Pipeline, MetresAsFloatGiveTheSameLabelsAsMillimetres) {
  Pipeline pipeline(kTabletop);
  DepthImage mm = bundled_mosd_frame(kMosd, "learn0");
  DepthImage m = mm;
  mm.depth.convertTo(m.depth, CV_32FC1, 0.001);
  const auto a = pipeline.process({{"depth", Packet::make(mm)}});
  const auto b = pipeline.process({{"depth", Packet::make(m)}});
  const auto* la = a.outputs.at("labels").get_if<LabelImage>();
  const auto* lb = b.outputs.at("labels").get_if<LabelImage>();
  ASSERT_TRUE(la != nullptr && lb != nullptr);
  EXPECT_EQ(la->count, lb->count);
  // Millimetres are exact in float; the median and the normals see the same values.
  EXPECT_TRUE(same_image(la->labels, lb->labels));
}

TEST(Pipeline, TwoPipelinesOnTwoThreadsGiveTheResultsOfOne) {
  std::vector<cv::Mat> reference;
  {
    Pipeline pipeline(kTabletop);
    for (const auto& stem : kStems) {
      reference.push_back(pipeline.process({{"depth", depth_packet(stem)}})
                              .outputs.at("labels")
                              .get_if<LabelImage>()
                              ->labels.clone());
    }
  }
  std::vector<std::vector<cv::Mat>> got(2);
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t) {
    threads.emplace_back([&, t] {
      Pipeline pipeline(kTabletop);
      for (const auto& stem : kStems) {
        got[static_cast<std::size_t>(t)].push_back(pipeline.process({{"depth", depth_packet(stem)}})
                                                       .outputs.at("labels")
                                                       .get_if<LabelImage>()
                                                       ->labels.clone());
      }
    });
  }
  for (auto& thread : threads)
    thread.join();
  for (const auto& run : got) {
    ASSERT_EQ(run.size(), reference.size());
    for (std::size_t i = 0; i < run.size(); ++i)
      EXPECT_TRUE(same_image(run[i], reference[i])) << kStems[i];
  }
}

TEST(Pipeline, AGraphWithoutInputsIsPulledFromItsOwnSourceToTheEnd) {
  const std::string yaml = R"(facet: 1
name: pulled
nodes:
  source: {stage: io.frames, params: {path: ")" +
                           kMosd.string() + R"(", labels_dir: ""}}
  median: {stage: filter.median, in: {depth: source.depth}}
outputs: {depth: median.depth}
)";
  Pipeline pipeline = Pipeline::from_text(yaml, source_dir() / "graphs/pulled.yaml");
  EXPECT_TRUE(pipeline.inputs().empty());
  std::vector<std::string> stems;
  for (int guard = 0; guard < 20; ++guard) {
    const FrameResult result = pipeline.process();
    if (result.end_of_stream) break;
    const auto* depth = result.outputs.at("depth").get_if<DepthImage>();
    ASSERT_NE(depth, nullptr);
    stems.push_back(depth->frame.stem);
  }
  EXPECT_EQ(stems.size(), kStems.size());
  pipeline.close();
  EXPECT_THROW(pipeline.process(), std::logic_error);
}

TEST(Pipeline, RunSinksWritesTheGraphsFilesToo) {
  TempDir out("facet-pipeline-sinks");
  PipelineOptions options;
  options.params["output"] = out.path().string();
  options.run_sinks = true;
  Pipeline pipeline(kTabletop, options);
  auto depth = bundled_mosd_frame(kMosd, "learn5");
  pipeline.process({{"depth", Packet::make(depth)}});
  pipeline.close();
  EXPECT_TRUE(std::filesystem::exists(out.path() / "labels/learn5.png"));
  EXPECT_TRUE(std::filesystem::exists(out.path() / "objects/learn5.json"));
  EXPECT_TRUE(std::filesystem::exists(out.path() / "overlay/learn5.png"));
}

}  // namespace
}  // namespace facet::test
