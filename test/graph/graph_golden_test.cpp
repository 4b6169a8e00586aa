// Golden tests of the diagnostics: every golden/*.yaml is loaded and validated against the test
// stages, and the printed diagnostics must equal golden/*.expected byte for byte.
//
// A first line `# args: --variant NAME --param k=v --set node.param=v` gives command-line options.
// After a deliberate change of wording, regenerate with FACET_UPDATE_GOLDEN=1 and review the diff.

#include <gtest/gtest.h>

#include <cstdlib>
#include <facet/framework/graph_spec.hpp>
#include <facet/framework/validated_graph.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_stages.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

fs::path golden_dir() {
  return fs::path(FACET_SOURCE_DIR) / "test" / "graph" / "golden";
}

std::vector<std::string> golden_cases() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(golden_dir())) {
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// `# args: ...` on the first line, split on spaces (golden files need no quoting).
LoadOptions options_from_header(const std::string& yaml) {
  LoadOptions options;
  const std::string prefix = "# args:";
  if (yaml.rfind(prefix, 0) != 0) return options;
  std::istringstream args(yaml.substr(prefix.size(), yaml.find('\n') - prefix.size()));
  std::string flag;
  std::string value;
  while (args >> flag >> value) {
    const std::size_t equals = value.find('=');
    if (flag == "--variant") {
      options.variant = value;
    } else if (flag == "--param") {
      options.params[value.substr(0, equals)] = value.substr(equals + 1);
    } else if (flag == "--set") {
      options.sets.emplace_back(value.substr(0, equals), value.substr(equals + 1));
    } else {
      ADD_FAILURE() << "unknown option in golden header: " << flag;
    }
  }
  return options;
}

// Replaces every occurrence of `from` in `text`.
std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t pos = text.find(from); pos != std::string::npos;
       pos = text.find(from, pos + to.size())) {
    text.replace(pos, from.size(), to);
  }
  return text;
}

std::string diagnostics_for(const std::string& name) {
  const fs::path file = golden_dir() / (name + ".yaml");
  Registry registry;
  graph_test::add_test_stages(registry);
  Diagnostics diagnostics;
  const GraphSpec graph = load_graph_file(file, options_from_header(read_text(file)), diagnostics);
  // Validation runs even after loading errors: everything is reported in one go.
  validate_graph(graph, registry, diagnostics);
  // Print the file as a user in the golden directory would see it.
  return replace_all(diagnostics.str(), golden_dir().string() + "/", "");
}

class GraphGolden : public testing::TestWithParam<std::string> {};

TEST_P(GraphGolden, DiagnosticsMatchTheExpectedText) {
  const fs::path expected_file = golden_dir() / (GetParam() + ".expected");
  const std::string actual = diagnostics_for(GetParam());
  const char* update = std::getenv("FACET_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    std::ofstream(expected_file, std::ios::binary) << actual;
  }
  ASSERT_TRUE(fs::exists(expected_file)) << expected_file.filename() << " is missing; got:\n"
                                         << actual;
  EXPECT_EQ(actual, read_text(expected_file));
  EXPECT_NE(actual.find("error: "), std::string::npos) << "a golden graph must be broken";
}

INSTANTIATE_TEST_SUITE_P(Cases, GraphGolden, testing::ValuesIn(golden_cases()),
                         [](const testing::TestParamInfo<std::string>& case_info) {
                           return case_info.param;
                         });

TEST(GraphGoldenSet, CoversEnoughCasesAndHasNoStrayExpectations) {
  const auto cases = golden_cases();
  EXPECT_GE(cases.size(), 12u);
  for (const auto& entry : fs::directory_iterator(golden_dir())) {
    if (entry.path().extension() != ".expected") continue;
    EXPECT_TRUE(fs::exists(fs::path(entry.path()).replace_extension(".yaml")))
        << entry.path().filename() << " has no graph";
  }
}

}  // namespace
}  // namespace facet
