// `facet compare --sweep` end to end, on a test stage that reports its own parameters as metrics
// (test/cli/plugins/sweep_probe_plugin.cpp): every point runs with its value, the reports carry
// the swept values, the plots are written, and bad sweeps are usage errors that say why.

#include <gtest/gtest.h>

#include <regex>

#include "cli_runner.hpp"
#include "headless_chromium.hpp"
#include "mini_xml.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

// A probe between the bundled frames and a depth writer; the variant fixes `count` at 6.
void write_probe_graph(const fs::path& file) {
  std::ofstream(file) << "facet: 1\nname: probe_graph\nparams: {output: out/probe}\nnodes:\n"
                      << "  source: {stage: io.frames, params: {path: "
                      << shell_quote((source_dir() / "data/mosd").string()) << "}}\n"
                      << "  probe: {stage: test.sweep_probe, in: {depth: source.depth}}\n"
                      << "  write: {stage: io.depth, in: {depth: probe.depth}, params: {dir: "
                         "\"${output}/depth\"}}\n"
                      << "variants:\n  doubled: {set: {probe.count: 6}}\n";
}

CliResult compare_probe(const fs::path& graph, const std::string& options, const fs::path& out) {
  return run_cli("compare " + shell_quote(graph.string()) + " --plugin-path " +
                 shell_quote(FACET_SWEEP_PROBE_PLUGIN_DIR) + " --frames 2 --warmup 0 " + options +
                 " --out " + shell_quote(out.string()));
}

// The text of variant `name`'s object in compare.json: from its name to the next variant's.
std::string variant_block(const std::string& json, const std::string& name) {
  const auto at = json.find("\"name\": \"" + name + "\"");
  if (at == std::string::npos) return {};
  const auto next = json.find("\"median_ms\"", json.find("\"metrics\"", at));
  return json.substr(at, next == std::string::npos ? std::string::npos : next - at);
}

double metric_mean(const std::string& block, const std::string& metric) {
  const std::regex pattern("\"node\": \"probe\",\\s*\"name\": \"" + metric +
                           "\",\\s*\"count\": 2,\\s*\"mean\": ([0-9.e+-]+)");
  std::smatch match;
  if (!std::regex_search(block, match, pattern)) return -1.0;
  return std::stod(match[1].str());
}

std::size_t png_files(const fs::path& dir) {
  std::size_t count = 0;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error))
    count += entry.path().extension() == ".png" ? 1 : 0;
  return count;
}

// Panel title -> points of each of its lines.
std::map<std::string, std::vector<std::size_t>> svg_lines(const fs::path& file) {
  const std::string text = read_file(file);
  MiniXmlParser parser(text);
  const auto root = parser.parse();
  EXPECT_TRUE(root.has_value()) << file << ": " << parser.error();
  std::map<std::string, std::vector<std::size_t>> lines;
  if (!root) return lines;
  for (const auto* group : root->all("g")) {
    if (group->attribute("class") != "panel") continue;
    auto& points = lines[group->attribute("data-title")];
    for (const auto* line : group->all("polyline"))
      points.push_back(polyline_points(*line));
  }
  return lines;
}

class CompareSweep : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir("facet-sweep");
    write_probe_graph(dir_->path() / "probe.yaml");
    result_ = new CliResult(compare_probe(dir_->path() / "probe.yaml",
                                          "--sweep probe.gain=0.0:1.0:0.1 --images 1",
                                          dir_->path() / "out"));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete dir_;
  }
  static fs::path out() { return dir_->path() / "out"; }
  static TempDir* dir_;
  static CliResult* result_;
};
TempDir* CompareSweep::dir_ = nullptr;
CliResult* CompareSweep::result_ = nullptr;

TEST_F(CompareSweep, EveryPointRunsWithItsValue) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  const std::string json = read_file(out() / "compare.json");
  for (int i = 0; i <= 10; ++i) {
    const std::string text = i == 10 ? "1.0" : "0." + std::to_string(i);
    const std::string block = variant_block(json, "probe.gain=" + text);
    ASSERT_FALSE(block.empty()) << text;
    const std::string json_value = i == 0 ? "0" : i == 10 ? "1" : text;
    EXPECT_NE(block.find("\"sweep\": {\n        \"probe.gain\": " + json_value + "\n"),
              std::string::npos)
        << block.substr(0, 300);
    EXPECT_DOUBLE_EQ(metric_mean(block, "gain"), i / 10.0) << text;
    EXPECT_DOUBLE_EQ(metric_mean(block, "count"), 3.0) << text;
    EXPECT_EQ(png_files(out() / ("probe.gain=" + text) / "depth"), 2u) << text;
  }
}

TEST_F(CompareSweep, TerminalShowsTheValuesTheBestAndThePlateau) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  EXPECT_NE(result_->out.find("probe_graph: 11 variant(s), 2 frame(s)"), std::string::npos)
      << result_->out;
  EXPECT_TRUE(
      std::regex_search(result_->out, std::regex(R"(\n  probe\.f +0\.897  probe\.gain=0\.3\n)")))
      << result_->out;
  EXPECT_NE(result_->out.find("plateau of probe.f (within 0.01 of its best 0.897): probe.gain 0.3 "
                              ".. 0.6 (4 points)"),
            std::string::npos)
      << result_->out;
}

TEST_F(CompareSweep, JsonAndCsvCarryTheSweep) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  const std::string json = read_file(out() / "compare.json");
  EXPECT_TRUE(std::regex_search(
      json, std::regex(R"re("param": "probe.gain",\s*"score": "probe.f",\s*"best": 0.897,\s*)re"
                       R"re("within": 0.01,\s*"from": 0.3,\s*"to": 0.6,\s*"points": 4)re")))
      << json.substr(0, 2500);
  EXPECT_TRUE(std::regex_search(
      json, std::regex(R"re("name": "probe.gain",\s*"node": "probe",\s*"param": "gain",\s*)re"
                       R"re("start": 0,\s*"stop": 1,\s*"step": 0.1)re")));
  const std::string csv = read_file(out() / "compare.csv");
  EXPECT_EQ(csv.rfind("variant,kind,node,stage,name,shared,count,median,p95,mean,probe.gain\n", 0),
            0u);
  EXPECT_NE(csv.find("probe.gain=0.4,metric,probe,,gain,,2,0.4,,0.4,0.4\n"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find("probe.gain=0.4,stage,probe,test.sweep_probe,call_ms,no,2,"),
            std::string::npos);
}

TEST_F(CompareSweep, PlotHasOnePanelPerScoreAndElevenPointsPerLine) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  const auto lines = svg_lines(out() / "sweep_probe.gain.svg");
  using Lines = std::vector<std::size_t>;
  // No eval stage in this graph: every stage's metrics are plotted, the source's too.
  EXPECT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines.at("source.valid_ratio"), Lines{11});
  EXPECT_EQ(lines.at("probe.f"), Lines{11});
  EXPECT_EQ(lines.at("probe.gain"), Lines{11});
  EXPECT_EQ(lines.at("probe.count"), Lines{11});
  EXPECT_EQ(lines.at("frame median ms"), Lines{11});
}

TEST_F(CompareSweep, ReportEmbedsThePlotAndLoadsNothing) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  const std::string html = read_file(out() / "report.html");
  EXPECT_NE(html.find("<h2>Sweep</h2>"), std::string::npos);
  EXPECT_NE(html.find("<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"sweep\""),
            std::string::npos);
  EXPECT_NE(html.find("Plateau of probe.f along probe.gain: 0.3 .. 0.6"), std::string::npos);
  EXPECT_NE(html.find("<th>probe.gain</th>"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href="), std::string::npos);
}

// The browser lays the plot's lines out as SVG: each has a width on the page.
TEST_F(CompareSweep, ReportPlotRendersInHeadlessChromium) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  if (!have_chromium()) GTEST_SKIP() << "chromium is not installed (Debian package 'chromium')";
  TempDir profile("facet-chromium");
  const fs::path dom_file = profile / "dom.html";
  ASSERT_EQ(load_in_headless_chromium(out() / "report.html", profile / "user", dom_file), 0);
  const std::string dom = read_file(dom_file);
  // Five panels of one line each.
  EXPECT_NE(dom.find("data-sweep-lines=\"5\""), std::string::npos) << dom.substr(0, 600);
}

TEST(CompareSweepGrid, EveryCombinationAndOnePlotPerParameter) {
  TempDir dir("facet-sweep");
  write_probe_graph(dir / "probe.yaml");
  const auto result = compare_probe(
      dir / "probe.yaml", "--sweep probe.gain=0.2:0.4:0.1 --sweep probe.count=1:2:1 --images 0",
      dir / "out");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const std::string json = read_file(dir / "out" / "compare.json");
  const std::string block = variant_block(json, "probe.gain=0.3,probe.count=2");
  ASSERT_FALSE(block.empty()) << json.substr(0, 1000);
  EXPECT_DOUBLE_EQ(metric_mean(block, "gain"), 0.3);
  EXPECT_DOUBLE_EQ(metric_mean(block, "count"), 2.0);
  EXPECT_TRUE(std::regex_search(
      block, std::regex(R"re("sweep": \{\s*"probe.gain": 0.3,\s*"probe.count": 2\s*\})re")));
  using Lines = std::vector<std::size_t>;
  // Along gain: one line per count (2), three points each; along count: one per gain.
  EXPECT_EQ(svg_lines(dir / "out" / "sweep_probe.gain.svg").at("probe.f"), (Lines{3, 3}));
  EXPECT_EQ(svg_lines(dir / "out" / "sweep_probe.count.svg").at("probe.f"), (Lines{2, 2, 2}));
  const std::string csv = read_file(dir / "out" / "compare.csv");
  EXPECT_NE(csv.find("probe.gain=0.3,probe.count=2\",metric,probe,,count,,2,2,,2,0.3,2\n"),
            std::string::npos)
      << csv.substr(0, 600);
}

TEST(CompareSweepVariant, SweepsOnTopOfTheVariant) {
  TempDir dir("facet-sweep");
  write_probe_graph(dir / "probe.yaml");
  const auto result =
      compare_probe(dir / "probe.yaml",
                    "--variant doubled --sweep probe.gain=0.1:0.2:0.1 --images 0", dir / "out");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("sweep on variant doubled"), std::string::npos) << result.out;
  const std::string json = read_file(dir / "out" / "compare.json");
  EXPECT_NE(json.find("\"variant\": \"doubled\""), std::string::npos);
  for (const char* name : {"probe.gain=0.1", "probe.gain=0.2"})
    EXPECT_DOUBLE_EQ(metric_mean(variant_block(json, name), "count"), 6.0) << name;
}

struct BadSweep {
  std::string options;
  int exit_code;
  std::string message;
};

// Two probes whose gain is one graph parameter, as graphs/tabletop.yaml's edge_threshold feeds
// both the edge filter and the normals' noise measure.
void write_graph_param_graph(const fs::path& file) {
  std::ofstream(file) << "facet: 1\nname: shared_gain\nparams: {output: out/probe, gain: 0.5}\n"
                      << "nodes:\n  source: {stage: io.frames, params: {path: "
                      << shell_quote((source_dir() / "data/mosd").string()) << "}}\n"
                      << "  probe: {stage: test.sweep_probe, in: {depth: source.depth}, params: "
                         "{gain: \"${gain}\"}}\n"
                      << "  second: {stage: test.sweep_probe, in: {depth: probe.depth}, params: "
                         "{gain: \"${gain}\", count: 4}}\n"
                      << "  write: {stage: io.depth, in: {depth: second.depth}, params: {dir: "
                         "\"${output}/depth\"}}\n";
}

double node_metric_mean(const std::string& block, const std::string& node,
                        const std::string& metric) {
  const std::regex pattern("\"node\": \"" + node + "\",\\s*\"name\": \"" + metric +
                           "\",\\s*\"count\": 2,\\s*\"mean\": ([0-9.e+-]+)");
  std::smatch match;
  if (!std::regex_search(block, match, pattern)) return -1.0;
  return std::stod(match[1].str());
}

TEST(CompareSweepGraphParam, MovesEveryNodeParameterWrittenWithIt) {
  TempDir dir("facet-sweep");
  write_graph_param_graph(dir / "shared.yaml");
  const auto result =
      compare_probe(dir / "shared.yaml", "--sweep gain=0.2:0.4:0.1 --images 0", dir / "out");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const std::string json = read_file(dir / "out" / "compare.json");
  for (const char* text : {"0.2", "0.3", "0.4"}) {
    const std::string block = variant_block(json, std::string("gain=") + text);
    ASSERT_FALSE(block.empty()) << text << "\n" << json.substr(0, 1000);
    EXPECT_DOUBLE_EQ(node_metric_mean(block, "probe", "gain"), std::stod(text)) << text;
    EXPECT_DOUBLE_EQ(node_metric_mean(block, "second", "gain"), std::stod(text)) << text;
    EXPECT_DOUBLE_EQ(node_metric_mean(block, "second", "count"), 4.0) << text;
  }
  EXPECT_TRUE(std::regex_search(
      json, std::regex(R"re("name": "gain",\s*"node": null,\s*"param": "gain")re")))
      << json.substr(json.rfind("\"sweep\""));
  EXPECT_TRUE(fs::exists(dir / "out" / "sweep_gain.svg"));
}

TEST(CompareSweepGraphParam, ASetNodeParameterIsNoLongerMoved) {
  TempDir dir("facet-sweep");
  write_graph_param_graph(dir / "shared.yaml");
  // --set takes probe's gain from the graph parameter; the sweep still moves second's.
  const auto result = compare_probe(
      dir / "shared.yaml", "--set probe.gain=0.9 --sweep gain=0.2:0.3:0.1 --images 0", dir / "out");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const std::string json = read_file(dir / "out" / "compare.json");
  const std::string block = variant_block(json, "gain=0.3");
  EXPECT_DOUBLE_EQ(node_metric_mean(block, "probe", "gain"), 0.9);
  EXPECT_DOUBLE_EQ(node_metric_mean(block, "second", "gain"), 0.3);
}

TEST(CompareSweepGraphParam, BadSweepsSayWhatIsWrong) {
  TempDir dir("facet-sweep");
  write_graph_param_graph(dir / "shared.yaml");
  const std::vector<BadSweep> cases = {
      {"--sweep gian=0:1:0.5", 2,
       "'gian' is no node.param and no graph parameter; did you mean "
       "'gain'?"},
      {"--sweep gain=0.5:1.5:0.5", 2,
       "graph parameter 'gain' sets parameter 'gain' of node 'probe' (real): value 1.5 is out of "
       "range [0.0, 1.0]"},
      {"--sweep gain=0:1:0.5 --param gain=0.1", 2, "'gain' is also given by --param gain=0.1"},
      {"--sweep gain=0:1:0.5 --sweep second.gain=0:1:0.5", 2,
       "it sets second.gain, which --sweep second.gain=0:1:0.5 sweeps too"},
      {"--sweep output=1:2:1", 2,
       "graph parameter 'output' sets parameter 'dir' of node 'write' (string) is not numeric"},
  };
  for (const auto& bad : cases) {
    const auto result = compare_probe(dir / "shared.yaml", bad.options, dir / "out");
    EXPECT_EQ(result.exit_code, bad.exit_code) << bad.options << "\n" << result.out;
    EXPECT_NE(result.out.find(bad.message), std::string::npos) << bad.options << "\n" << result.out;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CompareSweepErrors, SayWhatIsWrong) {
  TempDir dir("facet-sweep");
  write_probe_graph(dir / "probe.yaml");
  const std::vector<BadSweep> cases = {
      {"--sweep probe.gain=0.9:0.8:0.01", 2,
       "<command line>: error: --sweep probe.gain=0.9:0.8:0.01: start 0.9 is above stop 0.8"},
      {"--sweep probe.gain=0:1:0", 2, "step must be positive, got 0"},
      {"--sweep probe.gain=0:1:0.001", 2, "1001 points; at most 200"},
      {"--sweep prbe.gain=0:1:0.1", 2, "unknown node 'prbe'; did you mean 'probe'?"},
      {"--sweep probe.gian=0:1:0.1", 2,
       "stage 'test.sweep_probe' of node 'probe' has no parameter 'gian'; did you mean 'gain'?"},
      {"--sweep probe.gain=0.5:1.5:0.5", 2, "value 1.5 is out of range [0.0, 1.0]"},
      {"--sweep probe.label=1:2:1", 2, "parameter 'label' of node 'probe' (string) is not numeric"},
      {"--sweep probe.count=1:5:0.5", 2, "(int) takes whole numbers"},
      {"--sweep probe.gain=0:1:0.1 --set probe.gain=0.5", 2, "is also given by --set"},
      {"--sweep probe.gain=0:1:0.05 --sweep probe.count=0:10:1", 2,
       "the grid has 21 x 11 = 231 points; at most 200"},
      {"--sweep probe.gain=0:1:0.1 --variants base,doubled", 2, "give --variant V"},
      {"--variant doubled", 2, "selects where a --sweep starts"},
      {"--variant doubld --sweep probe.gain=0:1:0.5", 3, "unknown variant 'doubld'"},
  };
  for (const auto& bad : cases) {
    const auto result = compare_probe(dir / "probe.yaml", bad.options, dir / "out");
    EXPECT_EQ(result.exit_code, bad.exit_code) << bad.options << "\n" << result.out;
    EXPECT_NE(result.out.find(bad.message), std::string::npos) << bad.options << "\n" << result.out;
  }
  // Nothing ran: no point's folder was made.
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace facet::test
