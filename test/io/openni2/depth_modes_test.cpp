// Choosing a depth video mode, and intrinsics from a field of view: no device needed.

#include "openni2/depth_modes.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "facet/error.hpp"

namespace facet::openni2 {
namespace {

using ::testing::HasSubstr;

DepthMode mm(int width, int height, int fps) {
  return {width, height, fps, "1 mm", true};
}
DepthMode um(int width, int height, int fps) {
  return {width, height, fps, "100 um", false};
}

// An Xtion-like list: millimetre and 100-micrometre modes at several sizes and rates.
const std::vector<DepthMode> kModes = {um(640, 480, 30), mm(320, 240, 30), mm(320, 240, 60),
                                       mm(640, 480, 30), mm(160, 120, 30)};

std::string error_of(const ModeRequest& request, const DepthMode& current) {
  try {
    choose_depth_mode(kModes, current, request, "1d27/0601@2/5");
  } catch (const StageError& error) {
    return error.what();
  }
  return "";
}

TEST(DepthModes, DescribesAModeWithSizeRateAndFormat) {
  EXPECT_EQ(describe(mm(640, 480, 30)), "640x480 @ 30 fps, 1 mm");
}

TEST(DepthModes, AnEmptyRequestKeepsTheCurrentMillimetreMode) {
  EXPECT_EQ(choose_depth_mode(kModes, mm(320, 240, 60), {}, "u"), mm(320, 240, 60));
}

TEST(DepthModes, AnEmptyRequestSwitchesAMicrometreDefaultToMillimetresAtItsSize) {
  EXPECT_EQ(choose_depth_mode(kModes, um(640, 480, 30), {}, "u"), mm(640, 480, 30));
}

TEST(DepthModes, AnEmptyRequestFallsBackToTheFirstMillimetreMode) {
  EXPECT_EQ(choose_depth_mode(kModes, um(1280, 1024, 15), {}, "u"), mm(320, 240, 30));
}

TEST(DepthModes, ARequestPicksTheFirstMillimetreModeMatchingEveryFieldGiven) {
  EXPECT_EQ(choose_depth_mode(kModes, mm(320, 240, 30), {640, 480, 0}, "u"), mm(640, 480, 30));
  EXPECT_EQ(choose_depth_mode(kModes, mm(640, 480, 30), {0, 0, 60}, "u"), mm(320, 240, 60));
  EXPECT_EQ(choose_depth_mode(kModes, mm(640, 480, 30), {320, 240, 30}, "u"), mm(320, 240, 30));
}

TEST(DepthModes, AModeTheDeviceDoesNotListIsRefusedListingTheSupportedOnes) {
  const std::string error = error_of({1280, 960, 0}, mm(640, 480, 30));
  EXPECT_THAT(error, HasSubstr("'1d27/0601@2/5'"));
  EXPECT_THAT(error, HasSubstr("1280 width, 960 height, any fps"));
  for (const auto& mode : kModes)
    EXPECT_THAT(error, HasSubstr(describe(mode)));
}

TEST(DepthModes, AMicrometreOnlyMatchIsRefused) {
  // 640x480 @ 30 exists as 100 um and as 1 mm; at 60 fps it exists in neither.
  EXPECT_THAT(error_of({640, 480, 60}, mm(640, 480, 30)),
              HasSubstr("no depth mode in millimetres"));
  const std::vector<DepthMode> micrometres_only = {um(640, 480, 30)};
  EXPECT_THROW(choose_depth_mode(micrometres_only, um(640, 480, 30), {}, "u"), StageError);
}

TEST(DepthModes, IntrinsicsFromTheFieldOfViewPutTheImageEdgesAtHalfTheAngle) {
  const double hfov = 2.0 * std::atan(320.0 / 525.0);
  const double vfov = 2.0 * std::atan(240.0 / 525.0);
  const CameraIntrinsics camera = intrinsics_from_fov(640, 480, hfov, vfov);
  EXPECT_NEAR(camera.fx, 525.0, 1e-9);
  EXPECT_NEAR(camera.fy, 525.0, 1e-9);
  EXPECT_DOUBLE_EQ(camera.cx, 319.5);
  EXPECT_DOUBLE_EQ(camera.cy, 239.5);
  EXPECT_EQ(camera.width, 640);
  EXPECT_EQ(camera.height, 480);
  EXPECT_TRUE(camera.valid());
}

TEST(DepthModes, NoFieldOfViewGivesInvalidIntrinsics) {
  EXPECT_FALSE(intrinsics_from_fov(320, 240, 0.0, 0.0).valid());
  EXPECT_FALSE(intrinsics_from_fov(320, 240, std::nan(""), 0.8).valid());
  EXPECT_FALSE(intrinsics_from_fov(0, 240, 1.0, 0.8).valid());
  // A quarter turn across the width: fx is half the width.
  EXPECT_NEAR(intrinsics_from_fov(320, 240, std::numbers::pi / 2.0, 1.0).fx, 160.0, 1e-9);
}

}  // namespace
}  // namespace facet::openni2
