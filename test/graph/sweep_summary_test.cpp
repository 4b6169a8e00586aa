// What a sweep reports: scores per point, the best point of each, the plateau of F (on values
// worked out by hand), the sweep's fields in compare.json and compare.csv, and its SVG plot.
#include <gtest/gtest.h>

#include <cmath>
#include <facet/framework/compare_report.hpp>
#include <facet/framework/compare_summary.hpp>
#include <facet/framework/svg_plot.hpp>
#include <facet/framework/sweep_plot.hpp>
#include <facet/framework/sweep_summary.hpp>
#include <limits>
#include <regex>
#include <sstream>

#include "mini_xml.hpp"

namespace facet {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

SweepAxis axis_of(const std::string& option) {
  return std::get<SweepAxis>(parse_sweep_axis(option));
}

// A comparison of `points` whose score node reported `f` and `over_segmented`, and whose frame
// time is 10 + the point's index.
CompareSummary comparison(const std::vector<SweepPoint>& points, const std::vector<double>& f) {
  CompareSummary summary;
  summary.graph = "g";
  summary.frames = 4;
  summary.warmup = 1;
  for (std::size_t p = 0; p < points.size(); ++p) {
    VariantSummary variant;
    variant.name = points[p].name;
    variant.median_ms = 10.0 + static_cast<double>(p);
    variant.frame_ms = {variant.median_ms};
    variant.metrics.push_back({"score", "segments", 4, 3.0, 3.0, 3.0, 3.0});
    variant.metrics.push_back(
        {"score", "over_segmented", 4, 5.0 - static_cast<double>(p % 3), 0.0, 0.0, 0.0});
    if (!std::isnan(f[p])) variant.metrics.push_back({"score", "f", 4, f[p], f[p], f[p], f[p]});
    summary.variants.push_back(std::move(variant));
  }
  return summary;
}

// Eleven points, 0.80 .. 0.90; the best F (0.971) at 0.86. Within 0.01 of it (>= 0.961): 0.82 ..
// 0.86 (five points) and 0.89 alone; 0.87 (0.955) breaks the run.
const std::vector<double> kF = {0.90,  0.95,  0.965, 0.97, 0.962, 0.968,
                                0.971, 0.955, 0.93,  0.97, 0.90};

class OneAxisSweep : public ::testing::Test {
 protected:
  OneAxisSweep()
      : axes_({axis_of("edges.threshold=0.80:0.90:0.01")}),
        points_(expand_sweep_grid(axes_)),
        summary_(comparison(points_, kF)) {
    summary_.sweep = summarize_sweep(summary_, axes_, points_, "", 0.01);
  }
  std::vector<SweepAxis> axes_;
  std::vector<SweepPoint> points_;
  CompareSummary summary_;
};

TEST_F(OneAxisSweep, ScoresLeadWithFAndEndWithTheFrameTime) {
  const SweepSummary& sweep = *summary_.sweep;
  ASSERT_EQ(sweep.scores.size(), 4u);
  EXPECT_EQ(sweep.scores.front().key, "score.f");
  EXPECT_EQ(sweep.scores.back().key, "frame_ms");
  EXPECT_EQ(sweep.headline, "score.f");
  EXPECT_EQ(sweep.scores.front().values, kF);
}

TEST_F(OneAxisSweep, BestPointOfEachScoreFollowsItsGoal) {
  const SweepSummary& sweep = *summary_.sweep;
  EXPECT_EQ(sweep.find_score("score.f")->best, std::optional<std::size_t>(6));
  // The time is better low: the first point (10 ms).
  EXPECT_EQ(sweep.find_score("frame_ms")->best, std::optional<std::size_t>(0));
  // over_segmented 5, 4, 3, 5, 4, 3, ...: better low, the first 3 wins the tie.
  EXPECT_EQ(sweep.find_score("score.over_segmented")->best, std::optional<std::size_t>(2));
  // The number of segments describes the result but has no better direction.
  EXPECT_FALSE(sweep.find_score("score.segments")->best.has_value());
}

TEST_F(OneAxisSweep, PlateauIsTheWidestRunWithinTheToleranceOfTheBest) {
  const SweepSummary& sweep = *summary_.sweep;
  ASSERT_EQ(sweep.plateaus.size(), 1u);
  const SweepPlateau& plateau = sweep.plateaus.front();
  EXPECT_DOUBLE_EQ(plateau.best, 0.971);
  EXPECT_DOUBLE_EQ(plateau.from, 0.82);
  EXPECT_DOUBLE_EQ(plateau.to, 0.86);
  EXPECT_EQ(plateau.points, 5u);
  EXPECT_EQ(points_[plateau.first].name, "edges.threshold=0.82");
  EXPECT_TRUE(plateau.fixed.empty());
}

TEST_F(OneAxisSweep, ATighterToleranceNarrowsThePlateau) {
  // Within 0.002 of 0.971: 0.97 (0.83) and 0.971 (0.86) are not adjacent; 0.89 (0.97) neither:
  // each run is one point wide, and the first of them, 0.83, is reported.
  const SweepSummary tight = summarize_sweep(summary_, axes_, points_, "", 0.002);
  ASSERT_EQ(tight.plateaus.size(), 1u);
  EXPECT_EQ(tight.plateaus.front().points, 1u);
  EXPECT_DOUBLE_EQ(tight.plateaus.front().from, 0.83);
}

TEST_F(OneAxisSweep, TerminalNamesTheBestAndThePlateau) {
  std::ostringstream out;
  write_compare_table(out, summary_);
  const std::string text = out.str();
  EXPECT_NE(text.find("edges.threshold"), std::string::npos);
  EXPECT_TRUE(
      std::regex_search(text, std::regex(R"(\n  score\.f +0\.971  edges\.threshold=0\.86\n)")))
      << text;
  // The time is better low, and says so.
  EXPECT_TRUE(std::regex_search(
      text,
      std::regex(R"(\n  frame median ms +10  edges\.threshold=0\.80  \(lower is better\)\n)")))
      << text;
  EXPECT_NE(text.find("plateau of score.f (within 0.01 of its best 0.971): edges.threshold 0.82 "
                      ".. 0.86 (5 points)"),
            std::string::npos)
      << text;
}

TEST_F(OneAxisSweep, JsonHasTheSweptValuesBestAndPlateau) {
  std::ostringstream out;
  write_compare_json(out, summary_);
  const std::string json = out.str();
  EXPECT_NE(json.find(R"("name": "edges.threshold=0.85",
      "sweep": {
        "edges.threshold": 0.85
      },)"),
            std::string::npos)
      << json.substr(0, 2000);
  EXPECT_NE(json.find(R"("values": [)"), std::string::npos);
  EXPECT_NE(json.find(R"("headline": "score.f")"), std::string::npos);
  EXPECT_NE(json.find(R"("score": "score.f",
        "goal": "higher",
        "value": 0.971,
        "variant": "edges.threshold=0.86")"),
            std::string::npos)
      << json.substr(0, 3000);
  EXPECT_NE(json.find(R"("param": "edges.threshold",
        "score": "score.f",
        "best": 0.971,
        "within": 0.01,
        "from": 0.82,
        "to": 0.86,
        "points": 5)"),
            std::string::npos)
      << json.substr(0, 3000);
}

TEST_F(OneAxisSweep, CsvHasOneColumnPerSweptParameter) {
  std::ostringstream out;
  write_compare_csv(out, summary_);
  const std::string csv = out.str();
  EXPECT_EQ(
      csv.rfind("variant,kind,node,stage,name,shared,count,median,p95,mean,edges.threshold\n", 0),
      0u)
      << csv.substr(0, 200);
  EXPECT_NE(csv.find("edges.threshold=0.85,total,,,frame_ms,,1,15,0,,0.85\n"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find("edges.threshold=0.85,metric,score,,f,,4,0.968,,0.968,0.85\n"),
            std::string::npos)
      << csv;
}

TEST_F(OneAxisSweep, SvgIsWellFormedWithOneLinePerScoreAndEveryPoint) {
  const std::string svg = render_line_plot(sweep_plot(*summary_.sweep, 0));
  facet::test::MiniXmlParser parser(svg);
  const auto root = parser.parse();
  ASSERT_TRUE(root.has_value()) << parser.error() << "\n" << svg.substr(0, 500);
  EXPECT_EQ(root->name, "svg");
  EXPECT_EQ(root->attribute("xmlns"), "http://www.w3.org/2000/svg");
  const auto panels = root->all("g");
  std::vector<std::string> titles;
  for (const auto* group : panels) {
    if (group->attribute("class") != "panel") continue;
    titles.push_back(group->attribute("data-title"));
    const auto lines = group->all("polyline");
    ASSERT_EQ(lines.size(), 1u) << titles.back();
    EXPECT_EQ(facet::test::polyline_points(*lines.front()), 11u) << titles.back();
  }
  EXPECT_EQ(titles, (std::vector<std::string>{"score.f", "score.segments", "score.over_segmented",
                                              "frame median ms"}));
  // Three best points (segments has none), one plateau band, a legend.
  std::size_t best = 0;
  for (const auto* circle : root->all("circle"))
    best += circle->attribute("class") == "best" ? 1 : 0;
  EXPECT_EQ(best, 3u);
  std::size_t bands = 0;
  for (const auto* rect : root->all("rect"))
    bands += rect->attribute("class") == "band" ? 1 : 0;
  EXPECT_EQ(bands, 1u);
  EXPECT_NE(svg.find("class=\"legend\""), std::string::npos);
  EXPECT_NE(svg.find("plateau: score.f within 0.01 of its best"), std::string::npos);
}

TEST_F(OneAxisSweep, ScoreAxisFitsTheDataInsteadOfStartingAtZero) {
  const std::string svg = render_line_plot(sweep_plot(*summary_.sweep, 0));
  facet::test::MiniXmlParser parser(svg);
  const auto root = parser.parse();
  ASSERT_TRUE(root.has_value()) << parser.error();
  for (const auto* group : root->all("g")) {
    if (group->attribute("data-title") != "score.f") continue;
    std::vector<std::string> labels;
    for (const auto* text : group->all("text")) {
      if (text->attribute("text-anchor") == "end") labels.push_back(text->text);
    }
    // F from 0.90 to 0.971: ticks 0.90, 0.92, ... and no 0.
    ASSERT_FALSE(labels.empty());
    EXPECT_EQ(labels.front(), "0.90");
    EXPECT_EQ(std::find(labels.begin(), labels.end(), "0"), labels.end());
    EXPECT_EQ(std::find(labels.begin(), labels.end(), "0.00"), labels.end());
  }
}

TEST(SweepGridSummary, PlateauAlongEachAxisAndOneLinePerOtherValue) {
  const std::vector<SweepAxis> axes = {axis_of("a.x=1:4:1"), axis_of("b.y=0.1:0.2:0.1")};
  const auto points = expand_sweep_grid(axes);  // (x, y): (1,.1) (1,.2) (2,.1) (2,.2) ...
  // y = 0.1: 0.80 0.95 0.96 0.95 along x; y = 0.2: 0.96 0.96 0.90 0.70. Best 0.96.
  const std::vector<double> f = {0.80, 0.96, 0.95, 0.96, 0.96, 0.90, 0.95, 0.70};
  CompareSummary summary = comparison(points, f);
  const SweepSummary sweep = summarize_sweep(summary, axes, points, "v", 0.01);
  ASSERT_EQ(sweep.plateaus.size(), 2u);
  // Along x: on y = 0.1 the run x = 2..4 (0.95, 0.96, 0.95) is wider than y = 0.2's 1..2.
  EXPECT_EQ(sweep.plateaus[0].axis, 0u);
  EXPECT_DOUBLE_EQ(sweep.plateaus[0].from, 2.0);
  EXPECT_DOUBLE_EQ(sweep.plateaus[0].to, 4.0);
  EXPECT_EQ(sweep.plateaus[0].fixed,
            (std::vector<std::pair<std::string, std::string>>{{"b.y", "0.1"}}));
  // Along y: x = 2 (0.95, 0.96) is the first line within 0.01 at both values.
  EXPECT_DOUBLE_EQ(sweep.plateaus[1].from, 0.1);
  EXPECT_DOUBLE_EQ(sweep.plateaus[1].to, 0.2);
  EXPECT_EQ(sweep.plateaus[1].fixed,
            (std::vector<std::pair<std::string, std::string>>{{"a.x", "2"}}));

  const LinePlot plot = sweep_plot(sweep, 0);
  EXPECT_EQ(plot.x, (std::vector<double>{1, 2, 3, 4}));
  ASSERT_FALSE(plot.panels.empty());
  ASSERT_EQ(plot.panels.front().lines.size(), 2u);
  EXPECT_EQ(plot.panels.front().lines[0].label, "b.y=0.1");
  EXPECT_EQ(plot.panels.front().lines[1].y, (std::vector<double>{0.96, 0.96, 0.90, 0.70}));
  EXPECT_NE(plot.title.find("variant v"), std::string::npos);
  const std::string svg = render_line_plot(sweep_plot(sweep, 1));
  facet::test::MiniXmlParser parser(svg);
  const auto root = parser.parse();
  ASSERT_TRUE(root.has_value()) << parser.error();
  for (const auto* group : root->all("g")) {
    if (group->attribute("class") != "panel") continue;
    const auto lines = group->all("polyline");
    EXPECT_EQ(lines.size(), 4u);  // one per value of a.x
    for (const auto* line : lines)
      EXPECT_EQ(facet::test::polyline_points(*line), 2u);
  }
}

TEST(SweepGridSummary, MissingScoresAreGapsNotZeros) {
  const std::vector<SweepAxis> axes = {axis_of("a.x=1:3:1")};
  const auto points = expand_sweep_grid(axes);
  CompareSummary summary = comparison(points, {0.5, kNaN, 0.6});
  const SweepSummary sweep = summarize_sweep(summary, axes, points, "", 0.01);
  EXPECT_TRUE(std::isnan(sweep.find_score("score.f")->values[1]));
  const std::string svg = render_line_plot(sweep_plot(sweep, 0));
  facet::test::MiniXmlParser parser(svg);
  const auto root = parser.parse();
  ASSERT_TRUE(root.has_value()) << parser.error();
  for (const auto* group : root->all("g")) {
    if (group->attribute("data-title") == "score.f") {
      EXPECT_EQ(facet::test::polyline_points(*group->all("polyline").front()), 2u);
    }
  }
}

TEST(SweepGridSummary, ScoresAreTheEvalStagesMetricsWhenThereAreAny) {
  const std::vector<SweepAxis> axes = {axis_of("a.x=1:2:1")};
  const auto points = expand_sweep_grid(axes);
  CompareSummary summary = comparison(points, {0.5, 0.6});
  for (auto& variant : summary.variants) {
    variant.stages.push_back({"patches", "patches", "grow.surfaces"});
    variant.stages.push_back({"score", "score@x", "eval.groundtruth"});
    variant.metrics.push_back({"patches", "patches", 4, 12.0, 12.0, 12.0, 12.0});
  }
  const SweepSummary sweep = summarize_sweep(summary, axes, points, "", 0.01);
  EXPECT_EQ(sweep.find_score("patches.patches"), nullptr);
  EXPECT_NE(sweep.find_score("score.f"), nullptr);
  EXPECT_NE(sweep.find_score("frame_ms"), nullptr);
  // Without an eval stage, every metric is a score.
  for (auto& variant : summary.variants)
    variant.stages.pop_back();
  const SweepSummary plain = summarize_sweep(summary, axes, points, "", 0.01);
  EXPECT_NE(plain.find_score("patches.patches"), nullptr);
}

TEST(SweepGridSummary, TheGraphsHeadlineLeadsAndAHeadlineBetterLowHasItsPlateauAbove) {
  const std::vector<SweepAxis> axes = {axis_of("edges.threshold=0.80:0.90:0.01")};
  const auto points = expand_sweep_grid(axes);
  CompareSummary summary = comparison(points, kF);
  // over_segmented along the points: best 3 at 0.82 and 0.85; within 1 of it (<= 4): 0.81 ..
  // 0.83 and 0.85 alone.
  const std::vector<double> over_segmented = {5, 4, 3, 3.5, 5, 3, 5, 5, 5, 5, 5};
  for (std::size_t p = 0; p < points.size(); ++p)
    summary.variants[p].metrics[1].mean = over_segmented[p];
  summary.headline = Headline{"score", "over_segmented", ScoreGoal::lower, true, true, {}};
  const SweepSummary sweep = summarize_sweep(summary, axes, points, "", 1.0);
  EXPECT_EQ(sweep.headline, "score.over_segmented");
  EXPECT_EQ(sweep.scores.front().key, "score.over_segmented");
  EXPECT_EQ(sweep.scores[1].key, "score.f");
  ASSERT_EQ(sweep.plateaus.size(), 1u);
  EXPECT_EQ(sweep.plateaus.front().score, "score.over_segmented");
  EXPECT_DOUBLE_EQ(sweep.plateaus.front().best, 3.0);
  EXPECT_DOUBLE_EQ(sweep.plateaus.front().from, 0.81);
  EXPECT_DOUBLE_EQ(sweep.plateaus.front().to, 0.83);
  EXPECT_EQ(sweep.plateaus.front().points, 3u);
}

TEST(SweepGridSummary, AHeadlineNoPointReportedHasNoPlateauAndSaysSo) {
  const std::vector<SweepAxis> axes = {axis_of("a.x=1:3:1")};
  const auto points = expand_sweep_grid(axes);
  CompareSummary summary = comparison(points, {0.5, 0.6, 0.7});
  summary.headline = Headline{"score", "precison", ScoreGoal::higher, true, false, {}};
  summary.sweep = summarize_sweep(summary, axes, points, "", 0.01);
  EXPECT_EQ(summary.sweep->headline, "score.precison");
  EXPECT_EQ(summary.sweep->find_score("score.precison"), nullptr);
  EXPECT_TRUE(summary.sweep->plateaus.empty());
  std::ostringstream out;
  write_compare_table(out, summary);
  EXPECT_NE(out.str().find("no plateau: no point reported the headline metric 'score.precison'"),
            std::string::npos)
      << out.str();
}

TEST(SweepGridSummary, AHeadlineOfAStageOutsideEvalIsAScoreToo) {
  const std::vector<SweepAxis> axes = {axis_of("a.x=1:2:1")};
  const auto points = expand_sweep_grid(axes);
  CompareSummary summary = comparison(points, {0.5, 0.6});
  for (auto& variant : summary.variants) {
    variant.stages.push_back({"score", "score@x", "eval.groundtruth"});
    variant.metrics.push_back({"shapes", "fit_ms", 4, 2.0, 2.0, 2.0, 2.0});
  }
  summary.headline = Headline{"shapes", "fit_ms", ScoreGoal::lower, true, true, {}};
  const SweepSummary sweep = summarize_sweep(summary, axes, points, "", 0.01);
  ASSERT_NE(sweep.find_score("shapes.fit_ms"), nullptr);
  EXPECT_EQ(sweep.find_score("shapes.fit_ms")->goal, ScoreGoal::lower);
  EXPECT_EQ(sweep.scores.front().key, "shapes.fit_ms");
}

TEST(ScoreGoalOfAMetric, TimesAndSplitsAreBetterLowSceneCountsHaveNoBest) {
  EXPECT_EQ(goal_of_metric("f"), ScoreGoal::higher);
  EXPECT_EQ(goal_of_metric("fit_ms"), ScoreGoal::lower);
  EXPECT_EQ(goal_of_metric("latency_ms"), ScoreGoal::lower);
  EXPECT_EQ(goal_of_metric("over_segmented"), ScoreGoal::lower);
  EXPECT_EQ(goal_of_metric("segments"), ScoreGoal::none);
  EXPECT_EQ(goal_of_metric("msec"), ScoreGoal::higher);
  EXPECT_STREQ(goal_name(ScoreGoal::lower), "lower");
}

TEST(WidestRun, KnownValues) {
  const std::vector<double> x = {0, 1, 2, 3, 4, 5, 6};
  EXPECT_FALSE(widest_run_at_least(x, {0, 0, 0, 0, 0, 0, 0}, 1.0).has_value());
  auto run = widest_run_at_least(x, {1, 0, 1, 1, 1, 0, 1}, 1.0);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->first, 2u);
  EXPECT_EQ(run->last, 4u);
  // A NaN breaks a run.
  run = widest_run_at_least(x, {1, 1, kNaN, 1, 1, 1, 0}, 1.0);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->first, 3u);
  // Width in x, not in points: 2 points 10 apart beat 3 points 1 apart.
  run = widest_run_at_least({0, 1, 2, 3, 13}, {1, 1, 1, 0.5, 1}, 1.0);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->first, 0u);
  EXPECT_EQ(run->last, 2u);
  run = widest_run_at_least({0, 1, 2, 3, 13, 23}, {1, 1, 0, 0, 1, 1}, 1.0);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->first, 4u);
}

TEST(NiceTicks, RoundStepsInsideTheRange) {
  EXPECT_EQ(nice_ticks(0.0, 1.0, 5),
            (std::vector<double>{0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0}));
  const auto ticks = nice_ticks(0.893, 0.978, 4);
  ASSERT_GE(ticks.size(), 3u);
  EXPECT_GE(ticks.front(), 0.893);
  EXPECT_LE(ticks.back(), 0.978);
  EXPECT_EQ(tick_decimals(ticks[1] - ticks[0]), 2);
  EXPECT_EQ(tick_decimals(5.0), 0);
  EXPECT_EQ(tick_decimals(0.5), 1);
}

}  // namespace
}  // namespace facet
