// normals.cross's automatic smoothing: the noise measure, and the ladder of radii it picks from.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "facet/stage.hpp"
#include "normals/cross_stage.hpp"
#include "normals/normal_noise.hpp"
#include "normals/normal_smoothing.hpp"
#include "normals_test_support.hpp"

namespace {

using facet::normals::CrossStage;
using facet::normals::noisy_pair_share;
using facet::normals::NoisyPairRule;
using namespace facet::test;

// A normal image of one direction, with every `period`-th column tilted by `tilt_deg` about x.
cv::Mat striped_normals(double tilt_deg, int period) {
  cv::Mat normals(120, 160, CV_32FC3, cv::Scalar(0.0F, 0.0F, -1.0F));
  const auto t = static_cast<float>(tilt_deg * std::numbers::pi / 180.0);
  for (int v = 0; v < normals.rows; ++v) {
    for (int u = 0; u < normals.cols; u += period)
      normals.at<cv::Vec3f>(v, u) = cv::Vec3f(0.0F, std::sin(t), -std::cos(t));
  }
  return normals;
}

TEST(NoisyPairShare, CountsPairsFurtherApartThanTheAngle) {
  EXPECT_EQ(noisy_pair_share(striped_normals(0.0, 1), NoisyPairRule{}), 0.0);
  // Tilted columns at even u: the pair (u, u + 3) mixes a tilted and an untilted normal for every
  // u the rule samples (even), the pair (u, v + 3) never does: half of the pairs.
  EXPECT_NEAR(noisy_pair_share(striped_normals(40.0, 2), NoisyPairRule{}), 0.5, 1e-9);
  // Below the angle nothing counts.
  EXPECT_EQ(noisy_pair_share(striped_normals(30.0, 2), NoisyPairRule{}), 0.0);
  // Pairs with a missing normal are not pairs: with holes in the odd columns every pair along a row
  // reaches one, and the pairs along the columns agree (counted as noisy, the holes would make
  // half).
  cv::Mat holes = striped_normals(40.0, 2);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < holes.rows; ++v) {
    for (int u = 0; u < holes.cols; u += 2)
      holes.at<cv::Vec3f>(v, u + 1) = cv::Vec3f(nan, nan, nan);
  }
  EXPECT_EQ(noisy_pair_share(holes, NoisyPairRule{}), 0.0);
  EXPECT_EQ(noisy_pair_share(cv::Mat(10, 10, CV_32FC3, cv::Scalar(nan, nan, nan)), NoisyPairRule{}),
            0.0);
}

// A tilted plane 1 m away with Gaussian depth noise of `sigma_mm`, as float metres.
facet::DepthImage noisy_plane(double sigma_mm, std::uint64_t seed) {
  const auto scene = SceneBuilder().plane({0.0, 0.0, 1.0}, tilted_normal(35.0, 80.0)).render();
  facet::DepthImage depth = scene.depth_m_image();
  cv::RNG rng(seed);
  cv::Mat noise(depth.depth.size(), CV_32FC1);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma_mm / 1000.0);
  depth.depth = depth.depth + noise;
  return depth;
}

double metric(const facet::testing::StageRunner<CrossStage>& runner, const std::string& name) {
  for (const auto& m : runner.metrics()) {
    if (m.name == name) return m.value;
  }
  ADD_FAILURE() << "no metric " << name;
  return -1.0;
}

struct AutoRun {
  cv::Mat normals;
  double share = 0.0;
  double radius_px = 0.0;
  std::size_t warnings = 0;
};

AutoRun run_auto(const facet::DepthImage& depth, std::int64_t max_radius_px,
                 double edge_threshold = 0.85) {
  facet::testing::StageRunner<CrossStage> runner({{"auto_smooth_max_radius", max_radius_px},
                                                  {"auto_smooth_edge_threshold", edge_threshold},
                                                  {"image_depth", std::string("mm")}});
  runner.set_input("depth", facet::Packet::make(depth));
  runner.run();
  return {runner.output<facet::NormalImage>("normals").normals.clone(),
          metric(runner, "noisy_pair_share"), metric(runner, "smooth_radius_px"),
          runner.warnings().size()};
}

cv::Mat run_fixed(const facet::DepthImage& depth, std::int64_t radius_px) {
  return run_normals<CrossStage>(depth, {{"smooth_radius", radius_px},
                                         {"renormalize", radius_px > 0},
                                         {"image_depth", std::string("mm")}});
}

bool same_normals(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat ka = a.reshape(1);
  cv::Mat kb = b.reshape(1);
  for (int v = 0; v < ka.rows; ++v) {
    for (int u = 0; u < ka.cols; ++u) {
      const float x = ka.at<float>(v, u);
      const float y = kb.at<float>(v, u);
      if (!(x == y || (std::isnan(x) && std::isnan(y)))) return false;
    }
  }
  return true;
}

// The radius grows while one more radius of averaging makes at least the least gain (0.125) of
// the pairs agree: a quiet frame keeps its normals as they are, a noisy one is averaged with the
// radius where that stops, or with the largest allowed, with a warning when still more averaging
// would gain.
TEST(CrossAutoSmooth, SmoothsAsLittleAsSuffices) {
  constexpr double kMinGain = 0.125;
  const NoisyPairRule rule;
  bool saw_radius[3] = {false, false, false};
  for (const double sigma_mm : {0.3, 1.0, 2.0, 3.0, 4.0, 6.0}) {
    const facet::DepthImage depth = noisy_plane(sigma_mm, 2);
    const AutoRun a = run_auto(depth, 2);
    const auto radius_px = static_cast<int>(a.radius_px);
    ASSERT_GE(radius_px, 0);
    ASSERT_LE(radius_px, 2);
    saw_radius[radius_px] = true;
    EXPECT_TRUE(same_normals(a.normals, run_fixed(depth, radius_px))) << sigma_mm;
    // The shares of the box averages the stage chooses from.
    const auto share_of = [&](int r) { return noisy_pair_share(run_fixed(depth, r), rule); };
    EXPECT_DOUBLE_EQ(a.share, share_of(0));
    for (int r = 0; r < radius_px; ++r)
      EXPECT_GE(share_of(r) - share_of(r + 1), kMinGain) << sigma_mm << " mm, radius " << r;
    if (radius_px < 2) {
      EXPECT_LT(share_of(radius_px) - share_of(radius_px + 1), kMinGain) << sigma_mm;
      EXPECT_EQ(a.warnings, 0u) << sigma_mm;
    } else {
      // At the largest radius a warning says whether averaging the result once more would still
      // settle the least gain (looked at on every 8th row and column).
      NoisyPairRule coarse;
      coarse.stride_px = 8;
      cv::Mat again;
      facet::normals::NormalSmoother(1, true).apply(a.normals, again);
      const double gain_beyond =
          noisy_pair_share(a.normals, coarse) - noisy_pair_share(again, coarse);
      EXPECT_EQ(a.warnings, gain_beyond >= kMinGain ? 1u : 0u) << sigma_mm;
    }
  }
  // The noise levels cover the ladder: unsmoothed, and each radius.
  EXPECT_TRUE(saw_radius[0] && saw_radius[1] && saw_radius[2]);
}

// Noise that the largest radius allowed does not settle: the frame is averaged with it, and a
// warning says that more would still gain.
TEST(CrossAutoSmooth, WarnsWhenTheLargestRadiusIsNotEnough) {
  const facet::DepthImage depth = noisy_plane(6.0, 2);
  const AutoRun enough = run_auto(depth, 2);
  EXPECT_EQ(enough.radius_px, 2.0);
  EXPECT_EQ(enough.warnings, 0u);
  const AutoRun capped = run_auto(depth, 1);
  EXPECT_EQ(capped.radius_px, 1.0);
  EXPECT_TRUE(same_normals(capped.normals, run_fixed(depth, 1)));
  EXPECT_EQ(capped.warnings, 1u);
}

// The angle is the edge filter's: a stricter filter (a larger threshold) takes smaller
// disagreements for creases, so the same frame measures noisier and is smoothed where the
// paper's threshold leaves it as it is.
TEST(CrossAutoSmooth, MeasuresAgainstTheEdgeFiltersThreshold) {
  const facet::DepthImage depth = noisy_plane(1.0, 2);
  const AutoRun paper = run_auto(depth, 2);
  const AutoRun strict = run_auto(depth, 2, 0.97);
  EXPECT_EQ(paper.radius_px, 0.0);
  EXPECT_GE(strict.radius_px, 1.0);
  EXPECT_DOUBLE_EQ(paper.share, noisy_pair_share(run_fixed(depth, 0), NoisyPairRule{}));
  EXPECT_DOUBLE_EQ(strict.share,
                   noisy_pair_share(run_fixed(depth, 0), NoisyPairRule{.edge_threshold = 0.97}));
  EXPECT_GT(strict.share, paper.share + 0.125);
}

// Averaged normals need not be renormalised to be measured: the mean of unit vectors is shorter
// than 1 where they disagree, and the measure compares angles, not lengths.
TEST(NoisyPairShare, IgnoresTheLengthOfAveragedNormals) {
  const facet::DepthImage depth = noisy_plane(3.0, 5);
  for (const std::int64_t r : {1, 2}) {
    const cv::Mat mean =
        run_normals<CrossStage>(depth, {{"smooth_radius", r}, {"image_depth", std::string("mm")}});
    EXPECT_NEAR(noisy_pair_share(mean, NoisyPairRule{}),
                noisy_pair_share(run_fixed(depth, r), NoisyPairRule{}), 1e-3)
        << r;
  }
}

// Creases are not noise: a noise-free scene of many small boxes has many pairs across creases,
// which averaging keeps, so it is not smoothed.
TEST(CrossAutoSmooth, CreasesAreNotNoise) {
  SceneBuilder builder;
  for (int row = 0; row < 6; ++row) {
    for (int col = 0; col < 8; ++col) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = Eigen::Vector3d(-0.28 + 0.08 * col, -0.2 + 0.08 * row, 0.7);
      pose.linear() = (Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitX()) *
                       Eigen::AngleAxisd(0.5 + 0.1 * col, Eigen::Vector3d::UnitY()))
                          .toRotationMatrix();
      builder.box(pose, {0.025, 0.025, 0.025});
    }
  }
  const facet::DepthImage depth = builder.render().depth_m_image();
  const AutoRun a = run_auto(depth, 2);
  EXPECT_GT(a.share, 0.05);  // many creases
  EXPECT_EQ(a.radius_px, 0.0);
  EXPECT_EQ(a.warnings, 0u);
}

TEST(CrossAutoSmooth, OffByDefaultAndExclusiveWithAFixedRadius) {
  const facet::DepthImage depth = noisy_plane(3.0, 3);
  EXPECT_TRUE(same_normals(run_normals<CrossStage>(depth, {{"image_depth", std::string("mm")}}),
                           run_fixed(depth, 0)));
  try {
    facet::testing::StageRunner<CrossStage> runner(
        {{"auto_smooth_max_radius", std::int64_t{2}}, {"smooth_radius", std::int64_t{1}}});
    runner.set_input("depth", facet::Packet::make(depth));
    runner.run();
    FAIL() << "both radii accepted";
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find("set one of them to 0"), std::string::npos)
        << error.what();
  }
}

}  // namespace
