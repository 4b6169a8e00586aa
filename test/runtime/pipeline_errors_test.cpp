// facet::Pipeline's errors are the command line's: every problem of a graph, with file, line and
// column, as a GraphError; bad inputs from the host name the input; nothing exits the process.

#include <gtest/gtest.h>

#include "bundled_frames.hpp"
#include "cli_runner.hpp"
#include "facet/pipeline.hpp"

namespace facet::test {
namespace {

const std::filesystem::path kMosd = source_dir() / "data/mosd";
const std::filesystem::path kGraphName = source_dir() / "graphs/embedded.yaml";

std::string graph_with(const std::string& ports) {
  return "facet: 1\n"
         "name: embedded\n"
         "nodes:\n"
         "  source: {stage: io.frames, params: {path: \"" +
         kMosd.string() +
         "\", labels_dir: \"\"}}\n"
         "  median: {stage: filter.median, in: {depth: source.depth}}\n"
         "  points: {stage: convert.points, in: {depth: median.depth}}\n" +
         ports;
}

// The GraphError's text for `yaml`, or "" when it loads.
GraphError load_error(const std::string& yaml, const PipelineOptions& options = {}) {
  try {
    (void)Pipeline::from_text(yaml, kGraphName, options);
  } catch (const GraphError& error) {
    return error;
  }
  ADD_FAILURE() << "no GraphError for\n" << yaml;
  return GraphError("", {});
}

TEST(PipelineErrors, UnknownNodeOrPortOfAGraphPortIsReportedAtItsLine) {
  const GraphError error =
      load_error(graph_with("inputs: {depth: sourse.depth}\n"
                            "outputs: {points: points.pionts}\n"));
  const std::string text = error.what();
  EXPECT_NE(text.find("embedded.yaml:7:17: error: unknown node 'sourse' in graph input 'depth'"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("did you mean 'source'"), std::string::npos) << text;
  EXPECT_NE(text.find("embedded.yaml:8:19: error: stage 'convert.points' of node 'points' has "
                      "no output 'pionts'"),
            std::string::npos)
      << text;
  ASSERT_GE(error.diagnostics().size(), 2u);
  EXPECT_EQ(error.diagnostics()[0].line, 7);
  EXPECT_EQ(error.diagnostics()[0].severity, GraphDiagnostic::Severity::error);
}

TEST(PipelineErrors, MalformedAndMisnamedPortsAreErrors) {
  const std::string text =
      load_error(graph_with("outputs: {points: points, 2d: points.points}\n")).what();
  EXPECT_NE(text.find("malformed reference 'points' for graph output 'points'"), std::string::npos)
      << text;
  EXPECT_NE(text.find("invalid name '2d' in 'outputs'"), std::string::npos) << text;
}

TEST(PipelineErrors, AGraphWithNothingToReadIsAnError) {
  const std::string text = load_error(graph_with("")).what();
  EXPECT_NE(text.find("declares no 'outputs:'"), std::string::npos) << text;
}

TEST(PipelineErrors, ANodeReadingAnotherOutputOfAFedNodeIsAnError) {
  const std::string yaml = graph_with(
      "  sink: {stage: io.labels, in: {labels: source.labels}, params: {dir: out/x}}\n"
      "inputs: {depth: source.depth}\n"
      "outputs: {points: points.points}\n");
  PipelineOptions options;
  options.run_sinks = true;
  const std::string text = load_error(yaml, options).what();
  EXPECT_NE(text.find("node 'sink' reads 'source.labels', but node 'source' is not run"),
            std::string::npos)
      << text;
}

TEST(PipelineErrors, CommandLineStyleOptionsAreCheckedLikeTheCli) {
  PipelineOptions options;
  options.sets.emplace_back("median.sise", "5");
  options.variant = "fast";
  const std::string text =
      load_error(graph_with("outputs: {points: points.points}\n"), options).what();
  EXPECT_NE(text.find("unknown variant 'fast'"), std::string::npos) << text;
  EXPECT_NE(text.find("has no parameter 'sise'"), std::string::npos) << text;
}

TEST(PipelineErrors, AMissingGraphFileNamesTheFile) {
  try {
    Pipeline pipeline(source_dir() / "graphs/no-such-graph.yaml");
    FAIL() << "loaded a missing file";
  } catch (const GraphError& error) {
    EXPECT_NE(std::string(error.what()).find("no-such-graph.yaml: error: cannot read graph file"),
              std::string::npos)
        << error.what();
  }
}

TEST(PipelineErrors, BadInputsFromTheHostNameTheInput) {
  Pipeline pipeline = Pipeline::from_text(
      graph_with("inputs: {depth: source.depth}\noutputs: {points: points.points}\n"), kGraphName);
  const Packet depth = Packet::make(bundled_mosd_frame(kMosd, "learn0"));
  const auto message_of = [&](const std::map<std::string, Packet, std::less<>>& inputs) {
    try {
      pipeline.process(inputs);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message_of({}), "graph input 'depth' (facet.DepthImage/1) is missing");
  EXPECT_EQ(message_of({{"depth", depth}, {"rgb", depth}}),
            "graph 'embedded' has no input 'rgb'; its inputs are 'depth'");
  EXPECT_EQ(message_of({{"depth", Packet::make(LabelImage{})}}),
            "graph input 'depth' takes facet.DepthImage/1, got facet.LabelImage/1");
  EXPECT_EQ(message_of({{"depth", Packet()}}), "graph input 'depth' is empty");
  DepthImage eight_bit = bundled_mosd_frame(kMosd, "learn0");
  eight_bit.depth.convertTo(eight_bit.depth, CV_8UC1);  // neither millimetres nor metres
  EXPECT_EQ(message_of({{"depth", Packet::make(eight_bit)}}),
            "graph input 'depth' (facet.DepthImage/1): depth is CV_8UC1, must be CV_16UC1 (mm) "
            "or CV_32FC1 (m)");
  DepthImage cropped = bundled_mosd_frame(kMosd, "learn0");
  cropped.depth = cropped.depth(cv::Rect(0, 0, 320, 240)).clone();  // intrinsics still 640x480
  EXPECT_EQ(message_of({{"depth", Packet::make(cropped)}}),
            "graph input 'depth' (facet.DepthImage/1): depth is 320x240, its camera's "
            "intrinsics are 640x480");
  // The pipeline still works after refusing bad inputs.
  const auto result = pipeline.process({{"depth", depth}});
  EXPECT_NE(result.outputs.at("points").get_if<PointImage>(), nullptr);
}

TEST(PipelineErrors, AStageFailingOnAFrameIsAProcessErrorNamingTheNode) {
  Pipeline pipeline = Pipeline::from_text(
      graph_with("inputs: {depth: source.depth}\noutputs: {points: points.points}\n"), kGraphName);
  DepthImage depth = bundled_mosd_frame(kMosd, "learn0");
  depth.camera = {};  // a well-formed image, but convert.points cannot project it
  try {
    pipeline.process({{"depth", Packet::make(depth)}});
    FAIL() << "a depth image without intrinsics was projected";
  } catch (const ProcessError& error) {
    EXPECT_NE(std::string(error.what()).find("node 'points' (convert.points), frame 0"),
              std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("carries no camera intrinsics"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace facet::test
