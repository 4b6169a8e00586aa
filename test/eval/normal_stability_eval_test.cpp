#include "eval/normal_stability_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "eval/normal_deviation.hpp"
#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"

namespace facet::eval {
namespace {

using facet::testing::StageRunner;

// Normals facing the camera, tilted about the y axis by `tilt_deg` plus `ramp_deg` per column.
cv::Mat tilted_normals(double tilt_deg, double ramp_deg = 0.0) {
  cv::Mat normals(20, 30, CV_32FC3);
  for (int y = 0; y < normals.rows; ++y) {
    for (int x = 0; x < normals.cols; ++x) {
      const double angle = (tilt_deg + ramp_deg * x) * std::numbers::pi / 180.0;
      normals.at<cv::Vec3f>(y, x) = cv::Vec3f(static_cast<float>(std::sin(angle)), 0.0F,
                                              static_cast<float>(-std::cos(angle)));
    }
  }
  return normals;
}

std::map<std::string, double> run_frame(StageRunner<NormalStabilityEval>& runner,
                                        const cv::Mat& normals, const cv::Mat& planes = {}) {
  NormalImage image;
  image.normals = normals;
  runner.set_input("normals", Packet::make(image));
  if (!planes.empty()) {
    runner.set_input("plane_labels", Packet::make(LabelImage::counted(FrameHeader{}, planes)));
  }
  runner.run();
  std::map<std::string, double> metrics;
  for (const auto& metric : runner.metrics())
    metrics[metric.name] = metric.value;
  return metrics;
}

TEST(NormalStabilityEval, KnownRotationBetweenFrames) {
  StageRunner<NormalStabilityEval> runner({{"roi", std::string("5, 5, 10, 10")}});
  EXPECT_EQ(run_frame(runner, tilted_normals(0.0)).at("compared"), 0.0);
  auto metrics = run_frame(runner, tilted_normals(3.0));
  EXPECT_EQ(metrics.at("compared"), 1.0);
  EXPECT_EQ(metrics.at("points"), 100.0);
  EXPECT_NEAR(metrics.at("deviation_avg_deg"), 3.0, 1e-4);
  EXPECT_NEAR(metrics.at("deviation_max_deg"), 3.0, 1e-4);
  // Back by 1 degree: compared with the frame before, not the first.
  metrics = run_frame(runner, tilted_normals(2.0));
  EXPECT_NEAR(metrics.at("deviation_avg_deg"), 1.0, 1e-4);
}

TEST(NormalStabilityEval, AverageAndMaximumOverTheRegion) {
  // Frame 2 tilts column x by 0.1 x degrees: over columns 5..14 the mean is 0.95, the max 1.4.
  StageRunner<NormalStabilityEval> runner({{"roi", std::string("5, 5, 10, 10")}});
  run_frame(runner, tilted_normals(0.0));
  const auto metrics = run_frame(runner, tilted_normals(0.0, 0.1));
  EXPECT_NEAR(metrics.at("deviation_avg_deg"), 0.95, 1e-4);
  EXPECT_NEAR(metrics.at("deviation_max_deg"), 1.4, 1e-4);
}

TEST(NormalStabilityEval, InvalidNormalsAreLeftOut) {
  cv::Mat holes = tilted_normals(5.0);
  holes(cv::Rect(5, 5, 5, 10)).setTo(cv::Vec3f(NAN, NAN, NAN));
  const cv::Mat region = cv::Mat::zeros(20, 30, CV_8UC1);
  region(cv::Rect(5, 5, 10, 10)).setTo(255);
  const auto degrees = angular_deviations_deg(tilted_normals(0.0), holes, region);
  ASSERT_EQ(degrees.size(), 50u);
  EXPECT_NEAR(degrees.front(), 5.0, 1e-4);
}

TEST(NormalStabilityEval, LargestPlaneIsTheRegion) {
  // Plane 2 (left 20 columns) is the largest; only its normals change, by 4 degrees.
  cv::Mat planes = cv::Mat::zeros(20, 30, CV_32SC1);
  planes.colRange(0, 20).setTo(2);
  planes.colRange(20, 30).setTo(1);
  cv::Mat after = tilted_normals(0.0);
  tilted_normals(4.0).colRange(0, 20).copyTo(after.colRange(0, 20));
  after.colRange(20, 30).setTo(cv::Vec3f(1.0F, 0.0F, 0.0F));  // 90 degrees off, not in region
  StageRunner<NormalStabilityEval> runner;
  run_frame(runner, tilted_normals(0.0), planes);
  const auto metrics = run_frame(runner, after, planes);
  EXPECT_EQ(metrics.at("points"), 400.0);
  EXPECT_NEAR(metrics.at("deviation_max_deg"), 4.0, 1e-4);
}

TEST(NormalStabilityEval, ParsesTheRoi) {
  using Traits = facet::ParamTraits<facet::eval::PixelRect>;
  const auto rect = [](std::string_view text) {
    return std::get<facet::eval::PixelRect>(Traits::parse(text)).rect;
  };
  EXPECT_EQ(rect("1, 2,3 ,4"), cv::Rect(1, 2, 3, 4));
  EXPECT_TRUE(rect("").empty());
  EXPECT_EQ(Traits::format({cv::Rect(1, 2, 3, 4)}), "1, 2, 3, 4");
  EXPECT_EQ(Traits::format({}), "");
  for (const char* bad : {"1, 2, 3", "1, 2, 0, 4", "a, 2, 3, 4"}) {
    const auto parsed = Traits::parse(bad);
    ASSERT_TRUE(std::holds_alternative<std::string>(parsed)) << bad;
    EXPECT_NE(std::get<std::string>(parsed).find("is no rectangle"), std::string::npos);
  }
  EXPECT_THROW(StageRunner<NormalStabilityEval>({{"roi", std::string("1, 2, 3")}}),
               std::invalid_argument);
}

TEST(NormalStabilityEval, NoRegionIsAClearError) {
  StageRunner<NormalStabilityEval> runner;
  NormalImage image;
  image.normals = tilted_normals(0.0);
  runner.set_input("normals", Packet::make(image));
  EXPECT_THROW(runner.run(), StageError);
  StageRunner<NormalStabilityEval> outside({{"roi", std::string("100, 100, 10, 10")}});
  outside.set_input("normals", Packet::make(image));
  EXPECT_THROW(outside.run(), StageError);
}

}  // namespace
}  // namespace facet::eval
