// The generated scenes are physically plausible: objects rest on the table (or on each other),
// nothing sinks into the table. Checked on the depth images, back-projected with a camera pose
// worked out here from the stage's documented parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>

#include "synthetic/scene_layout.hpp"
#include "synthetic_runs.hpp"

namespace {

using facet::test::first_frame;
using facet::test::ParamMap;

// Height above the table top of the point the camera measured at pixel (u, v). The camera is
// `distance_m` from the table point at the image centre, looking down at `tilt_deg`: its height
// is distance * sin(tilt), and a camera point (x, y down, z forward) is at world height
// h - y cos(tilt) - z sin(tilt).
double height_above_table(const facet::DepthImage& depth, int u, int v, double distance_m,
                          double tilt_deg) {
  const double tilt = tilt_deg * std::numbers::pi / 180.0;
  const double z = depth.depth.at<std::uint16_t>(v, u) * 0.001;
  const double y = (v - depth.camera.cy) * z / depth.camera.fy;
  return distance_m * std::sin(tilt) - y * std::cos(tilt) - z * std::sin(tilt);
}

// The lowest measured point of every object, as height above the table.
std::map<std::int32_t, double> lowest_points(const facet::test::SyntheticFrame& frame) {
  std::map<std::int32_t, double> lowest;
  for (int v = 0; v < frame.labels.labels.rows; ++v) {
    for (int u = 0; u < frame.labels.labels.cols; ++u) {
      const auto id = frame.labels.labels.at<std::int32_t>(v, u);
      if (id == 0) continue;
      const double height = height_above_table(frame.depth, u, v, 0.95, 50.0);
      auto [it, inserted] = lowest.try_emplace(id, height);
      if (!inserted) it->second = std::min(it->second, height);
    }
  }
  return lowest;
}

ParamMap exact(const std::string& preset, std::int64_t seed) {
  return {{"preset", preset}, {"seed", seed}, {"noise", false}};
}

TEST(SyntheticScene, TableIsThePlaneTheCameraLooksAt) {
  const auto frame = first_frame(exact("separated3", 1));
  // Table pixels (label 0) in the lower half of the image, where the table fills the view.
  int table_px = 0;
  for (int v = 300; v < 480; v += 7) {
    for (int u = 0; u < 640; u += 7) {
      if (frame.labels.labels.at<std::int32_t>(v, u) != 0) continue;
      if (frame.depth.depth.at<std::uint16_t>(v, u) == 0) continue;
      EXPECT_NEAR(height_above_table(frame.depth, u, v, 0.95, 50.0), 0.0, 0.002)
          << "pixel " << u << ", " << v;
      ++table_px;
    }
  }
  EXPECT_GT(table_px, 1000);
}

// Objects standing on the table show their lowest measured point near the table plane: at it
// for boxes and cylinders, a little above it for spheres and rounded edges (the part below the
// equator facing the table is hidden from a camera looking down). In separated3 no object hides
// another's foot.
TEST(SyntheticScene, SeparatedObjectsRestOnTheTable) {
  for (std::int64_t seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto frame = first_frame(exact("separated3", seed));
    const auto lowest = lowest_points(frame);
    ASSERT_EQ(lowest.size(), 3u);
    for (const auto& [id, height] : lowest) {
      EXPECT_GT(height, -0.003) << "object " << id << " below the table";
      EXPECT_LT(height, 0.022) << "object " << id << " floats above the table";
    }
  }
}

// Nothing of any preset is below the table top.
TEST(SyntheticScene, NoObjectSinksIntoTheTable) {
  for (const std::string& preset : facet::synthetic::preset_names()) {
    SCOPED_TRACE(preset);
    const auto lowest = lowest_points(first_frame(exact(preset, 2)));
    for (const auto& [id, height] : lowest)
      EXPECT_GT(height, -0.003) << "object " << id;
  }
}

// Stacks: the upper objects' lowest visible points are on the lower objects' tops, well above
// the table; still nothing is below the table.
TEST(SyntheticScene, StackedObjectsStandOnOtherObjects) {
  for (std::int64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto frame = first_frame(exact("stacked_occluded", seed));
    const auto lowest = lowest_points(frame);
    ASSERT_EQ(lowest.size(), 9u);
    int raised = 0;
    for (const auto& [id, height] : lowest) {
      EXPECT_GT(height, -0.003) << "object " << id << " below the table";
      if (height > 0.04) ++raised;
    }
    // Three stacks (two, three and two objects) put four objects on others.
    EXPECT_GE(raised, 3);
    EXPECT_LE(raised, 4);
  }
}

// Occlusion: in stacked_occluded an object hides part of another, so some object pixels border
// pixels of another object that is farther away by a depth jump.
TEST(SyntheticScene, OccludingPairHidesPartOfAnObject) {
  for (std::int64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto frame = first_frame(exact("stacked_occluded", seed));
    const cv::Mat& labels = frame.labels.labels;
    const cv::Mat& depth = frame.depth.depth;
    int occluding_borders = 0;
    for (int v = 0; v + 1 < labels.rows; ++v) {
      for (int u = 0; u + 1 < labels.cols; ++u) {
        const auto a = labels.at<std::int32_t>(v, u);
        for (const auto& [du, dv] : {std::pair{1, 0}, std::pair{0, 1}}) {
          const auto b = labels.at<std::int32_t>(v + dv, u + du);
          if (a == 0 || b == 0 || a == b) continue;
          const int jump =
              std::abs(depth.at<std::uint16_t>(v, u) - depth.at<std::uint16_t>(v + dv, u + du));
          if (jump > 15) ++occluding_borders;
        }
      }
    }
    EXPECT_GT(occluding_borders, 10);
  }
}

}  // namespace
