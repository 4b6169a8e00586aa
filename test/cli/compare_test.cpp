// `facet compare` end to end on the bundled frames: the merged run, the four outputs, the
// per-variant folders and the report (compare_chromium_test.cpp: the report as a browser shows
// it).

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>
#include <sstream>

#include "cli_runner.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const fs::path kAbNormals = source_dir() / "graphs/ab_normals.yaml";
const fs::path kCompareTabletop = source_dir() / "graphs/compare_tabletop.yaml";

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++count;
  return count;
}

std::size_t png_files(const fs::path& dir) {
  std::size_t count = 0;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    if (entry.path().extension() == ".png") ++count;
  }
  return count;
}

// The merged run of two normal estimators: shared stages once, the rest per variant.
class CompareAbNormals : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir("facet-compare");
    result_ = new CliResult(run_cli("compare " + shell_quote(kAbNormals.string()) +
                                    " --variants cross_r2,pca5 --frames 3 --warmup 1 --images 2"
                                    " --out " +
                                    shell_quote(dir_->path().string())));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete dir_;
  }
  static TempDir* dir_;
  static CliResult* result_;
};
TempDir* CompareAbNormals::dir_ = nullptr;
CliResult* CompareAbNormals::result_ = nullptr;

TEST_F(CompareAbNormals, RunsAndPrintsATable) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  EXPECT_NE(result_->out.find("ab_normals: 2 variant(s), 3 frame(s), the first 1 left out"),
            std::string::npos)
      << result_->out;
  EXPECT_NE(result_->out.find("frame median ms"), std::string::npos);
  EXPECT_NE(result_->out.find("score.f"), std::string::npos) << result_->out;
}

TEST_F(CompareAbNormals, EachVariantWritesItsOwnFolder) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  for (const char* variant : {"cross_r2", "pca5"}) {
    EXPECT_EQ(png_files(dir_->path() / variant / "edges"), 3u) << variant;
    EXPECT_EQ(png_files(dir_->path() / variant / "patches"), 3u) << variant;
  }
  EXPECT_FALSE(fs::exists(dir_->path() / "edges"));
}

TEST_F(CompareAbNormals, JsonTellsSharedFromPrivateStages) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  const std::string json = read_file(dir_->path() / "compare.json");
  EXPECT_NE(json.find("\"graph\": \"ab_normals\""), std::string::npos) << json.substr(0, 400);
  EXPECT_NE(json.find("\"warmup\": 1"), std::string::npos);
  // The graph names no headline: the report leads with F, the first node's that reports one.
  EXPECT_TRUE(std::regex_search(
      json, std::regex(R"re("headline": \{\s*"metric": "score.f",\s*"better": "higher",\s*)re"
                       R"re("from_graph": false,\s*"reported": true)re")))
      << json.substr(0, 600);
  // median is upstream of the difference: one node, shared; normals differ: one per variant.
  const std::regex shared_median(
      R"re("node": "median",\s*"merged_id": "median",\s*"stage": "filter.median",\s*"role": "process",\s*"shared": true)re");
  EXPECT_TRUE(std::regex_search(json, shared_median));
  const std::regex private_normals(
      R"re("node": "normals",\s*"merged_id": "normals@pca5",\s*"stage": "normals.pca",\s*"role": "process",\s*"shared": false)re");
  EXPECT_TRUE(std::regex_search(json, private_normals));
  EXPECT_NE(json.find("\"merged_id\": \"patches@cross_r2\""), std::string::npos);
  // Two timed frames per variant (3 run, 1 warm-up).
  const std::regex frame_ms(R"re("frame_ms": \[\s*[0-9.e+-]+,\s*[0-9.e+-]+\s*\])re");
  EXPECT_EQ(std::distance(std::sregex_iterator(json.begin(), json.end(), frame_ms),
                          std::sregex_iterator()),
            2);
}

TEST_F(CompareAbNormals, CsvHasRowsForBothVariants) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  const std::string csv = read_file(dir_->path() / "compare.csv");
  EXPECT_EQ(csv.rfind("variant,kind,node,stage,name,shared,count,median,p95,mean\n", 0), 0u);
  EXPECT_NE(csv.find("cross_r2,total,,,frame_ms,,2,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("pca5,stage,normals,normals.pca,call_ms,no,2,"), std::string::npos);
  EXPECT_NE(csv.find("pca5,stage,median,filter.median,call_ms,yes,2,"), std::string::npos);
  EXPECT_NE(csv.find("pca5,metric,score,,f,,3,"), std::string::npos) << csv;
}

TEST_F(CompareAbNormals, ReportIsSelfContained) {
  ASSERT_EQ(result_->exit_code, 0) << result_->out;
  const std::string html = read_file(dir_->path() / "report.html");
  // Two folders (edges, patches) x two frames x (the input depth, the ground truth and two
  // variants).
  EXPECT_EQ(count_of(html, "<img src=\"data:image/png;base64,"), 16u);
  EXPECT_EQ(count_of(html, "<img"), 16u);
  EXPECT_EQ(count_of(html, "<th>input depth</th>"), 2u);
  EXPECT_EQ(count_of(html, "<th>ground truth</th>"), 2u);
  // Each variant's image has its F of that frame under it; the frames are where the two differ
  // most; the summary leads with the best F and says what each variant changes, and where the
  // figures came from.
  EXPECT_EQ(count_of(html, "<div class=\"score\">F 0."), 8u) << html.substr(0, 2000);
  EXPECT_NE(html.find("largest difference first"), std::string::npos);
  EXPECT_NE(html.find("<p class=\"headline\">Best F (mean over frames): <b>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"changes\">normals: normals.pca"), std::string::npos);
  EXPECT_NE(html.find("<p class=\"provenance\">facet "), std::string::npos);
  EXPECT_NE(html.find("<code>facet compare "), std::string::npos);
  EXPECT_EQ(count_of(html, "src=\"http"), 0u);
  EXPECT_EQ(count_of(html, "href="), 0u);
  EXPECT_EQ(count_of(html, "<link"), 0u);
  EXPECT_NE(html.find("<table id=\"summary\">"), std::string::npos);
  EXPECT_GE(count_of(html, "<svg class=\"chart\""), 2u);  // stage times and scores
  EXPECT_LT(html.size(), 3u * 1024u * 1024u);
}

TEST(Compare, ObjectPipelineScoresEveryVariant) {
  TempDir dir("facet-compare");
  const auto result = run_cli("compare " + shell_quote(kCompareTabletop.string()) +
                              " --variants base,convex --frames 2 --warmup 0 --images 1 --out " +
                              shell_quote(dir.path().string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const std::string json = read_file(dir / "compare.json");
  // Every variant scored both frames, with an F in (0, 1].
  const std::regex f_metric(
      R"re("node": "score",\s*"name": "f",\s*"count": 2,\s*"mean": ([0-9.e+-]+))re");
  std::size_t scored = 0;
  for (auto it = std::sregex_iterator(json.begin(), json.end(), f_metric);
       it != std::sregex_iterator(); ++it) {
    const double f = std::stod((*it)[1].str());
    EXPECT_GT(f, 0.0);
    EXPECT_LE(f, 1.0);
    ++scored;
  }
  EXPECT_EQ(scored, 2u) << json;
  // The graph names its headline, F.
  EXPECT_TRUE(std::regex_search(
      json, std::regex(R"re("headline": \{\s*"metric": "score.f",\s*"better": "higher",\s*)re"
                       R"re("from_graph": true,\s*"reported": true)re")))
      << json.substr(0, 600);
  EXPECT_EQ(png_files(dir / "base" / "overlay"), 2u);
  EXPECT_EQ(png_files(dir / "convex" / "labels"), 2u);
  EXPECT_NE(json.find("\"merged_id\": \"objects@convex\""), std::string::npos);
  EXPECT_NE(json.find("\"merged_id\": \"blobs\""), std::string::npos);
  // Each frame's name, and each variant's F of each frame with its frame.
  EXPECT_TRUE(std::regex_search(
      json, std::regex(R"re("frame_stems": \[\s*"learn[0-9]+",\s*"learn[0-9]+"\s*\])re")))
      << json;
  const std::regex f_values(
      R"re("name": "f",[^}]*"frames": \[\s*0,\s*1\s*\],\s*"values": \[\s*([0-9.e+-]+),\s*([0-9.e+-]+)\s*\])re");
  std::size_t per_frame = 0;
  for (auto it = std::sregex_iterator(json.begin(), json.end(), f_values);
       it != std::sregex_iterator(); ++it) {
    EXPECT_GT(std::stod((*it)[1].str()), 0.0);
    EXPECT_LE(std::stod((*it)[2].str()), 1.0);
    ++per_frame;
  }
  EXPECT_EQ(per_frame, 2u) << json;
}

// The figures docs/compare.md quotes come from the command named in the comment above each
// table: a change that moves a score fails here until the doc says the new figure. Times are left
// out (they depend on the machine); the scores do not.
std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t begin = line.find('|') + 1;
  for (std::size_t end = line.find('|', begin); end != std::string::npos;
       begin = end + 1, end = line.find('|', begin)) {
    std::string cell = line.substr(begin, end - begin);
    cell.erase(0, cell.find_first_not_of(' '));
    cell.erase(cell.find_last_not_of(' ') + 1);
    cells.push_back(cell);
  }
  return cells;
}

// "variant,metric,node,,name,,count,median,,mean" rows of compare.csv: (variant, node.name) → mean.
std::map<std::pair<std::string, std::string>, double> metric_means(const fs::path& csv) {
  std::map<std::pair<std::string, std::string>, double> means;
  std::istringstream lines(read_file(csv));
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> fields;
    std::istringstream parts(line);
    for (std::string field; std::getline(parts, field, ',');)
      fields.push_back(field);
    if (fields.size() >= 10 && fields[1] == "metric") {
      means[{fields[0], fields[2] + "." + fields[4]}] = std::stod(fields[9]);
    }
  }
  return means;
}

TEST(Compare, TheFiguresDocsCompareQuotesAreCurrent) {
  // Column heading in the doc → the metric of the `score` node that it shows (its mean).
  const std::map<std::string, std::string> columns = {
      {"F", "score.f"},
      {"precision", "score.precision"},
      {"recall", "score.recall"},
      {"objects F ≥ 0.75", "score.objects_f75_ratio"},
      {"patches per frame", "score.segments"},
      {"under-segmenting per frame", "score.under_segmented"}};
  const std::string doc = read_file(source_dir() / "docs/compare.md");
  const std::string marker = "<!-- figures of: facet compare ";
  std::size_t checked = 0;
  for (auto at = doc.find(marker); at != std::string::npos; at = doc.find(marker, at + 1)) {
    const auto close = doc.find(" -->", at);
    ASSERT_NE(close, std::string::npos);
    const std::string args = doc.substr(at + marker.size(), close - at - marker.size());
    const auto space = args.find(' ');
    TempDir dir("facet-doc-figures");
    const auto result =
        run_cli("compare " + shell_quote((source_dir() / args.substr(0, space)).string()) +
                args.substr(space) + " -q --images 0 --out " + shell_quote(dir.path().string()));
    ASSERT_EQ(result.exit_code, 0) << args << "\n" << result.out;
    const auto means = metric_means(dir / "compare.csv");

    // The table right after the comment: a header, a separator, then one row per variant.
    std::istringstream lines(doc.substr(close));
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line) && line.rfind('|', 0) != 0) {
    }
    const auto header = split_cells(line);
    std::getline(lines, line);  // | --- | --- |
    std::size_t rows = 0;
    while (std::getline(lines, line) && line.rfind('|', 0) == 0) {
      const auto cells = split_cells(line);
      ASSERT_EQ(cells.size(), header.size()) << line;
      // The variant is the first cell's first word, `quoted` or not.
      const bool quoted = cells[0].rfind('`', 0) == 0;
      const std::string variant = quoted ? cells[0].substr(1, cells[0].find('`', 1) - 1)
                                         : cells[0].substr(0, cells[0].find(' '));
      for (std::size_t c = 1; c < cells.size(); ++c) {
        const auto column = columns.find(header[c]);
        if (column == columns.end()) continue;
        const auto mean = means.find({variant, column->second});
        ASSERT_NE(mean, means.end()) << args << ": no " << column->second << " of " << variant;
        // As precise as the doc writes it: 0.964 is 0.9635 to 0.9645.
        const auto point = cells[c].find('.');
        const int decimals =
            point == std::string::npos ? 0 : static_cast<int>(cells[c].size() - point - 1);
        EXPECT_NEAR(std::stod(cells[c]), mean->second, 0.5 * std::pow(10.0, -decimals) + 1e-9)
            << "docs/compare.md, `facet compare " << args << "`: " << variant << " " << header[c]
            << " is now " << mean->second;
      }
      ++rows;
    }
    EXPECT_GE(rows, 2u) << args;
    ++checked;
  }
  EXPECT_GE(checked, 2u) << "the tables of docs/compare.md lost their '" << marker << "' comments";
}

TEST(Compare, UnknownVariantIsAGraphError) {
  TempDir dir("facet-compare");
  const auto result =
      run_cli("compare " + shell_quote(kAbNormals.string()) +
              " --variants cross_r2,nope --frames 1 --out " + shell_quote(dir.path().string()));
  EXPECT_EQ(result.exit_code, 3) << result.out;
  EXPECT_NE(result.out.find("unknown variant 'nope'"), std::string::npos) << result.out;
}

TEST(Compare, GraphWithoutVariantsNeedsVariantNames) {
  TempDir dir("facet-compare");
  const fs::path graph = dir / "plain.yaml";
  std::ofstream(graph) << "facet: 1\nnodes:\n  source: {stage: io.frames, params: {path: "
                       << shell_quote((source_dir() / "data/mosd").string()) << "}}\n";
  const auto result = run_cli("compare " + shell_quote(graph.string()) + " --out " +
                              shell_quote((dir / "out").string()));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("defines no variants"), std::string::npos) << result.out;
}

// A sink whose folder does not follow the graph's `output` writes below the variant's folder.
TEST(Compare, SinksOutsideTheOutputParamWriteBelowTheVariantsFolder) {
  TempDir dir("facet-compare");
  const fs::path graph = dir / "fixed.yaml";
  std::ofstream(graph) << "facet: 1\nnodes:\n"
                       << "  source: {stage: io.frames, params: {path: "
                       << shell_quote((source_dir() / "data/mosd").string()) << "}}\n"
                       << "  median: {stage: filter.median, in: {depth: source.depth}}\n"
                       << "  depth_out: {stage: io.depth, in: {depth: median.depth}, params: "
                          "{dir: "
                       << shell_quote((dir / "fixed").string()) << "}}\n"
                       << "variants:\n  m5: {set: {median.size: 5}}\n";
  const auto result =
      run_cli("compare " + shell_quote(graph.string()) + " --variants base,m5 --frames 2 --out " +
              shell_quote((dir / "out").string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(png_files(dir / "out" / "base" / "depth_out"), 2u);
  EXPECT_EQ(png_files(dir / "out" / "m5" / "depth_out"), 2u);
  EXPECT_FALSE(fs::exists(dir / "fixed"));
}

TEST(Compare, DuplicateVariantIsAUsageError) {
  TempDir dir("facet-compare");
  const auto result =
      run_cli("compare " + shell_quote(kAbNormals.string()) +
              " --variants pca5,pca5 --frames 1 --out " + shell_quote(dir.path().string()));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("given twice"), std::string::npos) << result.out;
}

}  // namespace
}  // namespace facet::test
