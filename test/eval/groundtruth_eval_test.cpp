#include "eval/groundtruth_eval.hpp"

#include <gtest/gtest.h>

#include <map>

#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"

namespace facet::eval {
namespace {

using facet::testing::StageRunner;

LabelImage labels(std::initializer_list<int> column_ids) {
  cv::Mat ids(3, static_cast<int>(column_ids.size()), CV_32SC1);
  int x = 0;
  for (const int id : column_ids)
    ids.col(x++).setTo(id);
  return LabelImage::counted(FrameHeader{}, ids);
}

std::map<std::string, double> metrics_of(const StageRunner<GroundTruthEval>& runner) {
  std::map<std::string, double> metrics;
  for (const auto& metric : runner.metrics())
    metrics[metric.name] = metric.value;
  return metrics;
}

TEST(GroundTruthEval, ReportsTheOverlapScores) {
  StageRunner<GroundTruthEval> runner;
  runner.set_input("labels", Packet::make(labels({4, 4, 5, 5, 5, 0})));
  runner.set_input("truth", Packet::make(labels({1, 1, 1, 1, 0, 0})));
  runner.run();
  const auto metrics = metrics_of(runner);
  EXPECT_EQ(metrics.at("scored"), 1.0);
  // Truth object 12 px; segment 4 has 6 px, all on it (IoU 6/12), segment 5 has 9 px, 6 on it
  // (IoU 6/15): the match is 1-4, so P = 6 / (6 + 9) and R = 6 / 12.
  EXPECT_DOUBLE_EQ(metrics.at("precision"), 6.0 / 15.0);
  EXPECT_DOUBLE_EQ(metrics.at("recall"), 6.0 / 12.0);
  EXPECT_EQ(metrics.at("matched"), 1.0);
  EXPECT_EQ(metrics.at("over_segmented"), 1.0);
  EXPECT_EQ(metrics.at("truth_objects"), 1.0);
  EXPECT_EQ(metrics.at("segments"), 2.0);
  EXPECT_TRUE(metrics.count("f") == 1 && metrics.count("objects_f75_ratio") == 1);
}

TEST(GroundTruthEval, FrameWithoutTruthIsSkippedNotAnError) {
  StageRunner<GroundTruthEval> runner;
  runner.set_input("labels", Packet::make(labels({1, 1, 0})));
  runner.run();
  auto metrics = metrics_of(runner);
  EXPECT_EQ(metrics.at("scored"), 0.0);
  EXPECT_EQ(metrics.count("f"), 0u);
  // An empty truth packet (io.frames without a label file) is the same.
  runner.set_input("truth", Packet());
  runner.run();
  metrics = metrics_of(runner);
  EXPECT_EQ(metrics.at("scored"), 0.0);
  EXPECT_EQ(metrics.count("f"), 0u);
}

TEST(GroundTruthEval, MismatchingSizesAreAStageError) {
  StageRunner<GroundTruthEval> runner;
  runner.set_input("labels", Packet::make(labels({1, 1, 0})));
  runner.set_input("truth", Packet::make(labels({1, 1})));
  try {
    runner.run();
    FAIL() << "expected a StageError";
  } catch (const StageError& error) {
    EXPECT_NE(std::string(error.what()).find("same size"), std::string::npos) << error.what();
  }
}

TEST(GroundTruthEval, TruthBackgroundParameter) {
  StageRunner<GroundTruthEval> runner({{"truth_background", std::string("1, 3")}});
  runner.set_input("labels", Packet::make(labels({5, 6, 7})));
  runner.set_input("truth", Packet::make(labels({1, 2, 3})));
  runner.run();
  const auto metrics = metrics_of(runner);
  EXPECT_EQ(metrics.at("truth_objects"), 1.0);
  EXPECT_DOUBLE_EQ(metrics.at("precision"), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(metrics.at("recall"), 1.0);
}

// truth_background is a structured parameter: its parser runs where values are validated.
TEST(TruthBackground, AcceptsListsAndRejectsJunkWithTheReason) {
  using Traits = facet::ParamTraits<facet::eval::LabelIds>;
  EXPECT_TRUE(std::get<facet::eval::LabelIds>(Traits::parse("")).ids.empty());
  EXPECT_EQ(std::get<facet::eval::LabelIds>(Traits::parse("1, 4,7")).ids,
            (std::set<std::int32_t>{1, 4, 7}));
  EXPECT_EQ(Traits::format({{1, 4, 7}}), "1, 4, 7");
  EXPECT_EQ(std::get<std::string>(Traits::parse("1,x")),
            "'x' is not a positive label id (expected e.g. \"1\" or \"1, 4\")");
  EXPECT_EQ(std::get<std::string>(Traits::parse("1,,2")), "empty entry in '1,,2'");
  EXPECT_TRUE(std::holds_alternative<std::string>(Traits::parse("0")));
  // The runner validates like facet validate: the stage is never built with a bad list.
  try {
    StageRunner<GroundTruthEval> runner({{"truth_background", std::string("1, x")}});
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("truth_background"), std::string::npos);
  }
}

}  // namespace
}  // namespace facet::eval
