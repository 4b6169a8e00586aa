// The pipelined executor writes exactly what the sequential executor writes: graphs/tabletop.yaml
// on the bundled frames, every output file compared byte by byte.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "bundled_plugins.hpp"
#include "facet/framework/diagnostics.hpp"
#include "facet/framework/executor.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/pipelined_executor.hpp"
#include "facet/framework/registry.hpp"
#include "facet/framework/validated_graph.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;

using facet::test::bundled_plugins;

// Every file under `dir`, by path relative to it, with its bytes.
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    files[fs::relative(entry.path(), dir).string()] =
        std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return files;
}

class ExecutorEquivalenceTest : public ::testing::Test {
 protected:
  facet::ValidatedGraph tabletop(const fs::path& output, facet::Diagnostics& diagnostics) {
    facet::LoadOptions options;
    options.params = {{"input", (fs::path(FACET_SOURCE_DIR) / "data/mosd").string()},
                      {"output", output.string()}};
    spec_ = facet::load_graph_file(fs::path(FACET_SOURCE_DIR) / "graphs/tabletop.yaml", options,
                                   diagnostics);
    return facet::validate_graph(spec_, bundled_plugins(), diagnostics);
  }

  facet::GraphSpec spec_;
};

TEST_F(ExecutorEquivalenceTest, PipelinedWritesTheSameBytesAsSequentialOnTheTabletopGraph) {
  const facet::test::TempDir dir("facet-executors");
  facet::RunOptions options;
  options.max_frames = 4;  // a few frames keep the sanitizer builds quick
  std::vector<std::string> sequential_warnings;
  options.on_warning = [&](const std::string& w) { sequential_warnings.push_back(w); };

  facet::Diagnostics diagnostics;
  const auto sequential_graph = tabletop(dir / "sequential", diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
  facet::SequentialExecutor sequential(sequential_graph);
  const auto expected_stats = sequential.run(options);
  ASSERT_EQ(expected_stats.frames, 4);
  const auto expected = files_under(dir / "sequential");
  ASSERT_FALSE(expected.empty());

  for (const auto& [threads, in_flight] : {std::pair{2, 2}, std::pair{3, 5}, std::pair{2, 1}}) {
    const std::string name =
        "pipelined-" + std::to_string(threads) + "-" + std::to_string(in_flight);
    const auto graph = tabletop(dir / name, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.str();
    std::vector<std::string> warnings;
    options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
    facet::PipelinedExecutor pipelined(graph, {threads, in_flight});
    const auto stats = pipelined.run(options);
    EXPECT_EQ(stats.frames, expected_stats.frames) << name;
    // The same warnings in the same order: they are reported as frames leave the pipeline.
    EXPECT_EQ(warnings, sequential_warnings) << name;
    const auto actual = files_under(dir / name);
    ASSERT_EQ(actual.size(), expected.size()) << name;
    for (const auto& [file, bytes] : expected) {
      const auto it = actual.find(file);
      ASSERT_NE(it, actual.end()) << name << ": " << file << " missing";
      EXPECT_TRUE(it->second == bytes) << name << ": " << file << " differs";
    }
    // Every metric but the stages' own timings ("..._ms").
    for (std::size_t n = 0; n < stats.nodes.size(); ++n) {
      for (const auto& [metric, values] : expected_stats.nodes[n].metrics) {
        if (metric.ends_with("_ms")) continue;
        EXPECT_EQ(stats.nodes[n].metrics.at(metric), values) << stats.nodes[n].id << " " << metric;
      }
      EXPECT_EQ(stats.nodes[n].call_ms.size(), expected_stats.nodes[n].call_ms.size());
      EXPECT_EQ(stats.nodes[n].skipped, expected_stats.nodes[n].skipped);
    }
  }
}

}  // namespace
