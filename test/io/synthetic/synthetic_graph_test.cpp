// graphs/synthetic.yaml run through the framework with the bundled plugins: it writes the
// dataset layout, and io.frames reads back exactly what io.synthetic generated.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "bundled_plugins.hpp"
#include "facet/framework/diagnostics.hpp"
#include "facet/framework/executor.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/validated_graph.hpp"
#include "facet/testing/stage_runner.hpp"
#include "io/frames_source.hpp"
#include "synthetic_runs.hpp"
#include "temp_dir.hpp"

namespace {

using facet::test::bundled_plugins;
using facet::test::generate;
using facet::test::same_image;

// Runs graphs/synthetic.yaml with the graph params; returns the error text, empty on success.
std::string run_synthetic_graph(const std::map<std::string, std::string>& params) {
  facet::Diagnostics diagnostics;
  facet::LoadOptions options;
  options.params = params;
  const facet::GraphSpec spec = facet::load_graph_file(
      std::filesystem::path(FACET_SOURCE_DIR) / "graphs/synthetic.yaml", options, diagnostics);
  const facet::ValidatedGraph graph = facet::validate_graph(spec, bundled_plugins(), diagnostics);
  if (diagnostics.has_errors()) return diagnostics.str();
  try {
    facet::SequentialExecutor executor(graph);
    executor.run();
  } catch (const facet::RunError& error) {
    return error.what();
  }
  return "";
}

TEST(SyntheticGraph, WritesTheDatasetLayoutThatIoFramesReadsBack) {
  const facet::test::TempDir dir("facet-synthetic-graph");
  const auto output = dir.path() / "scenes";
  ASSERT_EQ(run_synthetic_graph({{"preset", "touching_pairs"},
                                 {"seed", "9"},
                                 {"frames", "3"},
                                 {"output", output.string()}}),
            "");
  EXPECT_TRUE(std::filesystem::exists(output / "intrinsics.yaml"));
  for (int i = 0; i < 3; ++i) {
    const std::string name = "touching_pairs_9_00000" + std::to_string(i) + ".png";
    EXPECT_TRUE(std::filesystem::exists(output / "depth" / name)) << name;
    EXPECT_TRUE(std::filesystem::exists(output / "label" / name)) << name;
  }

  const auto generated =
      generate({{"preset", std::string("touching_pairs")}, {"seed", std::int64_t{9}}}, 3);
  ASSERT_EQ(generated.size(), 3u);
  facet::testing::StageRunner<facet::io::FramesSource> reader({{"path", output.string()}});
  for (const auto& expected : generated) {
    SCOPED_TRACE(expected.depth.frame.stem);
    reader.run();
    ASSERT_FALSE(reader.at_end_of_stream());
    const auto& depth = reader.output<facet::DepthImage>("depth");
    const auto& labels = reader.output<facet::LabelImage>("labels");
    EXPECT_EQ(depth.frame.stem, expected.depth.frame.stem);
    EXPECT_EQ(depth.camera, expected.depth.camera);
    EXPECT_TRUE(same_image(depth.depth, expected.depth.depth));
    EXPECT_TRUE(same_image(labels.labels, expected.labels.labels));
    EXPECT_EQ(labels.count, facet::synthetic::preset_object_count("touching_pairs"));
  }
  reader.run();
  EXPECT_TRUE(reader.at_end_of_stream());
}

TEST(SyntheticGraph, AnUnknownPresetIsRejectedBeforeAnythingRuns) {
  const facet::test::TempDir dir("facet-synthetic-graph");
  const std::string error =
      run_synthetic_graph({{"preset", "tower"}, {"output", (dir.path() / "x").string()}});
  EXPECT_NE(error.find("preset"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x" / "depth"));
}

}  // namespace
