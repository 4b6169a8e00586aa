// `facet compare` leads with the graph's `headline:` metric: the report's first paragraph, the
// summary table's first score column, the images' captions, the terminal and compare.json; and
// a headline that no variant reported is a warning and a paragraph saying so, not a crash.

#include <gtest/gtest.h>

#include <regex>

#include "cli_runner.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const fs::path kCompareTabletop = source_dir() / "graphs/compare_tabletop.yaml";

// graphs/compare_tabletop.yaml with another headline.
fs::path write_graph_with_headline(const TempDir& dir, const std::string& headline) {
  const fs::path graph = dir / "headline.yaml";
  std::ofstream(graph) << "facet: 1\nname: headline\nextends: "
                       << shell_quote(kCompareTabletop.string()) << "\nheadline: " << headline
                       << "\n";
  return graph;
}

// The mean of metric `name` of node `score` in each variant's part of compare.json, in order.
std::vector<double> means_of(const std::string& json, const std::string& name) {
  const std::regex pattern("\"node\": \"score\",\\s*\"name\": \"" + name +
                           "\",\\s*\"count\": [0-9]+,\\s*\"mean\": ([0-9.e+-]+)");
  std::vector<double> means;
  for (auto it = std::sregex_iterator(json.begin(), json.end(), pattern);
       it != std::sregex_iterator(); ++it) {
    means.push_back(std::stod((*it)[1].str()));
  }
  return means;
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++count;
  return count;
}

TEST(CompareHeadline, TheReportLeadsWithTheGraphsHeadline) {
  TempDir dir("facet-headline");
  const fs::path graph = write_graph_with_headline(dir, "score.precision");
  const auto result =
      run_cli("compare " + shell_quote(graph.string()) +
              " --variants base,convex --frames 2 --warmup 0 --images 1 --image-width 80 --out " +
              shell_quote((dir / "out").string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(result.out.find("warning"), std::string::npos) << result.out;

  const std::string json = read_file(dir / "out" / "compare.json");
  const auto precision = means_of(json, "precision");
  ASSERT_EQ(precision.size(), 2u) << json.substr(0, 2000);
  ASSERT_NE(precision[0], precision[1]) << "the two variants must differ for this test";
  const std::string best = precision[0] > precision[1] ? "base" : "convex";
  const std::string other = best == "base" ? "convex" : "base";
  EXPECT_NE(json.find(R"("headline": {
    "metric": "score.precision",
    "better": "higher",
    "from_graph": true,
    "reported": true,
    "best": ")" + best +
                      "\""),
            std::string::npos)
      << json.substr(0, 600);

  const std::string html = read_file(dir / "out" / "report.html");
  EXPECT_NE(html.find("<p class=\"headline\">Best precision (score.precision, mean over frames): "
                      "<b>" +
                      best + "</b> "),
            std::string::npos)
      << html.substr(0, 4000);
  EXPECT_EQ(html.find("Best F"), std::string::npos);
  // The headline's column comes first among the scores, its best value marked; F follows.
  const auto headline_column = html.find("<th>variant</th><th class=\"headline\">precision</th>");
  EXPECT_NE(headline_column, std::string::npos) << html.substr(0, 4000);
  EXPECT_LT(headline_column, html.find("<th>F</th>"));
  EXPECT_EQ(count_of(html, "<th>precision</th>"), 0u);
  EXPECT_EQ(count_of(html, "<td class=\"headline best\">"), 1u);
  EXPECT_NE(html.find("<tr><td>" + best + "</td><td class=\"headline best\">"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>" + other + "</td><td class=\"headline\">"), std::string::npos);
  // Under each variant's image: its precision of the frame, not its F.
  EXPECT_GE(count_of(html, "<div class=\"score\">precision 0."), 2u);
  EXPECT_EQ(count_of(html, "<div class=\"score\">F "), 0u);
  EXPECT_NE(html.find("The frames whose precision differs most"), std::string::npos);

  EXPECT_NE(result.out.find("best score.precision (the headline, higher is better): " + best),
            std::string::npos)
      << result.out;
}

TEST(CompareHeadline, AHeadlineNoVariantReportedIsAWarningAndSaidInTheReport) {
  TempDir dir("facet-headline");
  const fs::path graph = write_graph_with_headline(dir, "score.precison");
  const auto result = run_cli("compare " + shell_quote(graph.string()) +
                              " --variants base,convex --frames 1 --warmup 0 --images 0 --out " +
                              shell_quote((dir / "out").string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  // At the graph's `headline:` line, with what the node reported instead (in name order).
  EXPECT_NE(result.out.find(graph.string() +
                            ":4:11: warning: headline score.precison: no variant reported it; "
                            "node 'score' reported f, matched, "),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("did you mean 'score.precision'?"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("headline score.precison: no variant reported it\n"), std::string::npos)
      << result.out;

  const std::string html = read_file(dir / "out" / "report.html");
  EXPECT_NE(html.find("<p class=\"headline missing\">The graph's headline metric "
                      "<b>score.precison</b> was reported by no variant: node &apos;score&apos; "
                      "reported f, "),
            std::string::npos)
      << html.substr(0, 4000);
  EXPECT_EQ(html.find("<p class=\"headline\">"), std::string::npos);
  EXPECT_EQ(html.find("class=\"headline best\""), std::string::npos);
  // The other scores are still there, F first as without a headline.
  EXPECT_NE(html.find("<th>variant</th><th>F</th><th>precision</th>"), std::string::npos);

  const std::string json = read_file(dir / "out" / "compare.json");
  EXPECT_NE(json.find(R"("headline": {
    "metric": "score.precison",
    "better": "higher",
    "from_graph": true,
    "reported": false
  })"),
            std::string::npos)
      << json.substr(0, 600);
}

}  // namespace
}  // namespace facet::test
