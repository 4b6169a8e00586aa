// The Kinect v1 noise model on a flat wall facing the camera: axial noise as Nguyen et al.'s
// model says, depth on the levels of 1/8 px disparity, range limits and grazing-angle dropouts.
#include "synthetic/kinect_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <set>

#include "synthetic/ray_caster.hpp"
#include "synthetic/scene.hpp"

namespace {

using facet::synthetic::CameraRig;
using facet::synthetic::KinectNoise;
using facet::synthetic::RandomStream;
using facet::synthetic::Scene;
using facet::synthetic::Shape;
using facet::synthetic::Solid;
using facet::synthetic::Vec3;

const facet::CameraIntrinsics kCamera{525.0, 525.0, 159.5, 119.5, 320, 240};

// A plane at distance `distance_m`, seen head-on (camera looking straight down at it), or tilted
// by looking at it from `tilt_deg` above its surface.
cv::Mat measure_plane(double distance_m, const KinectNoise& noise, double tilt_deg = 90.0,
                      std::uint64_t seed = 1) {
  Scene scene;
  scene.solids.push_back({Solid{Shape::plane, Vec3(0, 0, 0), cv::Matx33d::eye(), Vec3(), 0.0}, 0});
  const CameraRig rig = CameraRig::looking_at(kCamera, Vec3(0, 0, 0), distance_m, tilt_deg, 0.075);
  const auto ideal = facet::synthetic::render_ideal(scene, rig, 10.0);
  RandomStream random(seed);
  return facet::synthetic::measure_depth(ideal, scene, rig, noise, random);
}

struct Statistics {
  double mean_mm = 0.0;
  double sigma_mm = 0.0;
  std::set<int> values;
};

Statistics statistics(const cv::Mat& depth_mm) {
  Statistics result;
  cv::Scalar mean;
  cv::Scalar sigma;
  cv::meanStdDev(depth_mm, mean, sigma, depth_mm > 0);
  result.mean_mm = mean[0];
  result.sigma_mm = sigma[0];
  for (int v = 0; v < depth_mm.rows; ++v) {
    for (int u = 0; u < depth_mm.cols; ++u) {
      if (const int value = depth_mm.at<std::uint16_t>(v, u); value > 0)
        result.values.insert(value);
    }
  }
  return result;
}

TEST(KinectNoise, AxialSigmaFollowsTheModelAtOneAndTwoMetres) {
  const KinectNoise noise;
  // Nguyen et al.: 1.88 mm at 1 m and 6.06 mm at 2 m head-on; at 60 deg incidence the angular
  // term adds 0.1 mm * (pi/3)^2 / (pi/6)^2 = 0.4 mm at 1 m.
  EXPECT_NEAR(noise.axial_sigma_m(1.0), 0.0012 + 0.0019 * 0.36, 1e-12);
  EXPECT_NEAR(noise.axial_sigma_m(2.0), 0.0012 + 0.0019 * 2.56, 1e-12);
  EXPECT_NEAR(noise.axial_sigma_m(1.0, std::numbers::pi / 3.0), 0.0012 + 0.0019 * 0.36 + 0.0004,
              1e-12);
  for (const double distance_m : {1.0, 2.0}) {
    SCOPED_TRACE("distance " + std::to_string(distance_m) + " m");
    // The depth delivered (quantised, rounded to mm) has the model's sigma; head-on over the
    // image (incidence below 37 deg), the angular term adds less than 0.1 mm.
    const Statistics measured = statistics(measure_plane(distance_m, noise));
    const double expected_mm = 1000.0 * noise.axial_sigma_m(distance_m);
    EXPECT_NEAR(measured.sigma_mm, expected_mm, 0.15 * expected_mm);
    EXPECT_NEAR(measured.mean_mm, 1000.0 * distance_m, 0.5 * expected_mm);
  }
  // Two metres are noisier than one, as the quadratic model says (about 3x).
  const double near = statistics(measure_plane(1.0, noise)).sigma_mm;
  const double far = statistics(measure_plane(2.0, noise)).sigma_mm;
  EXPECT_GT(far, 2.5 * near);
}

TEST(KinectNoise, DepthLiesOnTheLevelsOfQuantisedDisparity) {
  const KinectNoise noise;
  const double focal_baseline = noise.ir_focal_px * noise.baseline_m;
  for (const double distance_m : {1.0, 2.0}) {
    SCOPED_TRACE("distance " + std::to_string(distance_m) + " m");
    const Statistics measured = statistics(measure_plane(distance_m, noise));
    ASSERT_GE(measured.values.size(), 3u) << "no noise";
    // Each value is one level of disparity k/8 px, up to the rounding to mm.
    for (const int value : measured.values) {
      const double levels = focal_baseline / (value * 0.001) / noise.disparity_step_px;
      EXPECT_NEAR(levels, std::round(levels), 0.2) << value << " mm";
    }
    // Neighbouring levels are a whole step apart: z^2 / (f b) / 8, 2.9 mm at 1 m, 11.5 mm at 2 m.
    const double step_mm = 1000.0 * distance_m * distance_m / focal_baseline / 8.0;
    int previous = *measured.values.begin();
    for (auto it = std::next(measured.values.begin()); it != measured.values.end(); ++it) {
      EXPECT_GT(*it - previous, 0.7 * step_mm) << "between " << previous << " and " << *it;
      previous = *it;
    }
  }
}

TEST(KinectNoise, WithoutAxialNoiseAFlatWallIsOneLevel) {
  KinectNoise noise;
  noise.axial_noise_scale = 0.0;
  EXPECT_EQ(statistics(measure_plane(1.5, noise)).values.size(), 1u);
  noise.enabled = false;
  const Statistics exact = statistics(measure_plane(1.5, noise));
  ASSERT_EQ(exact.values.size(), 1u);
  EXPECT_EQ(*exact.values.begin(), 1500);
}

TEST(KinectNoise, RangeLimitsAndGrazingAngles) {
  const KinectNoise noise;
  // Nearer than min_depth_m or beyond max_depth_m: nothing measured.
  EXPECT_EQ(cv::countNonZero(measure_plane(0.4, noise)), 0);
  EXPECT_EQ(cv::countNonZero(measure_plane(4.5, noise)), 0);
  // A plane 0.5 m away, seen from 15 deg above it: the top rows meet it at 86-88 deg incidence
  // and lose most pixels (the chance grows from 0 at 80 deg to 1 at 89 deg); the bottom rows
  // (62-64 deg, 0.27 m away: nearer than the Kinect measures, so min_depth_m is lowered) lose
  // none.
  KinectNoise near_range = noise;
  near_range.min_depth_m = 0.2;
  const cv::Mat grazing = measure_plane(0.5, near_range, 15.0);
  const int upper = cv::countNonZero(grazing(cv::Rect(0, 0, 320, 30)));
  const int lower = cv::countNonZero(grazing(cv::Rect(0, 210, 320, 30)));
  EXPECT_EQ(lower, 320 * 30);
  EXPECT_LT(upper, 0.5 * 320 * 30);
  EXPECT_GT(upper, 0.02 * 320 * 30);
}

TEST(KinectNoise, SameSeedSameNoise) {
  const KinectNoise noise;
  cv::Mat differ;
  cv::compare(measure_plane(1.2, noise, 90.0, 5), measure_plane(1.2, noise, 90.0, 5), differ,
              cv::CMP_NE);
  EXPECT_EQ(cv::countNonZero(differ), 0);
  cv::compare(measure_plane(1.2, noise, 90.0, 5), measure_plane(1.2, noise, 90.0, 6), differ,
              cv::CMP_NE);
  EXPECT_GT(cv::countNonZero(differ), 1000);
}

}  // namespace
