// The hard-case kinds and presets: open containers seen inside and out as one object, flat
// objects of their thickness, cans lying along a line on the table, the presets' objects, and
// the drawn camera, table edge and wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "synthetic/household_objects.hpp"
#include "synthetic/ray_caster.hpp"
#include "synthetic/scene_layout.hpp"
#include "synthetic/shells.hpp"
#include "synthetic/view_setup.hpp"
#include "synthetic_runs.hpp"

namespace {

using facet::synthetic::RandomStream;
using facet::synthetic::Ray;
using facet::synthetic::Scene;
using facet::synthetic::Shape;
using facet::synthetic::Solid;
using facet::synthetic::Vec3;
using facet::test::generate;
using facet::test::label_pixels;
using facet::test::ParamMap;
using facet::test::same_image;

const std::vector<std::string> kHardPresets = {"on_flat", "pile20", "office", "containers"};

// A scene of the table plane (label 0) and one object (label 1).
Scene alone(const Solid& solid) {
  Scene scene;
  scene.solids.push_back(
      {Solid{Shape::plane, Vec3(0, 0, 0), facet::synthetic::Mat3::eye(), Vec3(), 0.0}, 0});
  scene.solids.push_back({solid, 1});
  scene.object_count = 1;
  return scene;
}

// The height of the first surface a ray straight down through (x, y) meets, and its label.
std::pair<double, int> drop(const Scene& scene, double x, double y) {
  const Ray ray{Vec3(x, y, 2.0), Vec3(0, 0, -1)};
  const auto hit = facet::synthetic::first_hit(scene, ray, 0.0, 10.0);
  if (!hit) return {-1.0, -1};
  return {2.0 - hit->hit.t, hit->label};
}

TEST(SyntheticHardCase, CupIsOpenWithABottomAndARim) {
  const Solid cup = facet::synthetic::cup(0.1, 0.2, 0.0, 0.04, 0.05, 0.004);
  const Scene scene = alone(cup);
  // Through the open top onto the inside of the bottom, one wall thickness above the table.
  const auto [floor_z, floor_label] = drop(scene, 0.1, 0.2);
  EXPECT_NEAR(floor_z, 0.004, 1e-9);
  EXPECT_EQ(floor_label, 1);
  // Onto the rim, between the inner and outer radius, at the cup's height.
  const auto [rim_z, rim_label] = drop(scene, 0.1 + 0.038, 0.2);
  EXPECT_NEAR(rim_z, 0.1, 1e-9);
  EXPECT_EQ(rim_label, 1);
  // Beside the cup: the table.
  EXPECT_EQ(drop(scene, 0.1 + 0.041, 0.2).second, 0);
  // A slanting ray into the cup meets the inside of the far wall, its normal towards the axis.
  const Ray slant{Vec3(0.1 - 0.2, 0.2, 0.3), Vec3(0.2 + 0.03, 0.0, -0.3 + 0.07)};
  const auto inner = facet::synthetic::first_hit(scene, slant, 0.0, 10.0);
  ASSERT_TRUE(inner);
  EXPECT_EQ(inner->label, 1);
  const Vec3 p = slant.origin + inner->hit.t * slant.direction;
  EXPECT_NEAR(std::hypot(p[0] - 0.1, p[1] - 0.2), 0.036, 1e-9);
  EXPECT_LT(inner->hit.normal[0], -0.99) << "the inner wall faces the axis";
}

TEST(SyntheticHardCase, BowlShowsItsInsideAndOutsideAsOneObject) {
  const double sphere_radius = 0.08;
  const double half_height = 0.025;
  const double wall = 0.005;
  const Solid bowl = facet::synthetic::bowl(0.0, 0.1, 0.0, sphere_radius, half_height, wall);
  const Scene scene = alone(bowl);
  // Straight down through the middle: the inside of the bottom, wall / 2 above the table.
  const auto [floor_z, floor_label] = drop(scene, 0.0, 0.1);
  EXPECT_NEAR(floor_z, 0.5 * wall, 1e-9);
  EXPECT_EQ(floor_label, 1);
  // The inner surface elsewhere lies on the inner sphere, below the rim.
  const double centre_z =
      facet::synthetic::bowl_sphere_centre_z(sphere_radius, half_height, wall) + half_height;
  const auto [inner_z, inner_label] = drop(scene, 0.03, 0.1);
  EXPECT_EQ(inner_label, 1);
  EXPECT_NEAR(std::hypot(0.03, inner_z - centre_z), sphere_radius - wall, 1e-9);
  EXPECT_LT(inner_z, 2 * half_height);

  // Seen by the default camera: pixels of the inside (normal towards the sphere centre) and
  // of the outside (normal away from it), all with the bowl's label.
  const auto rig = facet::synthetic::CameraRig::looking_at({525, 525, 319.5, 239.5, 640, 480},
                                                           Vec3(0, 0, 0), 0.95, 50.0, 0.075);
  const auto frame = facet::synthetic::render_ideal(scene, rig, 4.0);
  int inside_px = 0;
  int outside_px = 0;
  const Vec3 sphere_centre(0.0, 0.1, centre_z);
  for (int v = 0; v < frame.labels.rows; ++v) {
    for (int u = 0; u < frame.labels.cols; ++u) {
      const Vec3 point = frame.points.at<cv::Vec3d>(v, u);
      const Vec3 normal = frame.normals.at<cv::Vec3d>(v, u);
      // Everything above the table plane is the bowl.
      if (point[2] < 1e-9 || frame.depth_m.at<double>(v, u) <= 0.0) continue;
      EXPECT_EQ(frame.labels.at<std::int32_t>(v, u), 1) << "pixel " << u << ", " << v;
      const double radial = (point - sphere_centre).dot(normal);
      if (radial < 0.0) ++inside_px;
      if (radial > 0.0 && normal[2] < 0.99) ++outside_px;
    }
  }
  EXPECT_GT(inside_px, 500);
  EXPECT_GT(outside_px, 100);
}

TEST(SyntheticHardCase, FlatObjectsTopAtTheirThicknessAboveTheTable) {
  using Maker = Solid (*)(RandomStream&);
  const std::vector<std::pair<std::string, Maker>> makers = {
      {"book", facet::synthetic::book},
      {"magazine", facet::synthetic::magazine},
      {"tray", facet::synthetic::tray},
      {"tin", facet::synthetic::flat_tin}};
  for (const auto& [name, make] : makers) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      SCOPED_TRACE(name + " seed " + std::to_string(seed));
      RandomStream random(seed);
      const Solid flat = make(random);
      const double thickness = 2.0 * flat.half_size[2];
      EXPECT_GE(thickness, name == "magazine" ? 0.008 : 0.01);
      EXPECT_LE(thickness, name == "magazine" ? 0.012 : 0.04);
      // Across: the smaller side 10 cm or more, the larger 30 cm or less.
      const double across = 2.0 * std::max(flat.half_size[0], flat.half_size[1]);
      EXPECT_GE(2.0 * std::min(flat.half_size[0], flat.half_size[1]), 0.1 - 1e-12);
      EXPECT_LE(across, 0.3 + 1e-12);
      const auto [top_z, label] = drop(alone(flat), flat.centre[0], flat.centre[1]);
      EXPECT_EQ(label, 1);
      EXPECT_NEAR(top_z, thickness, 1e-9);
    }
  }
}

// Horizontal rays across the can's axis, 0.1 mm above the table, meet it all along its length;
// 0.1 mm below the table top nothing is there: it touches the table along a line.
TEST(SyntheticHardCase, LyingCanTouchesTheTableAlongALine) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    RandomStream random(seed);
    const Solid can = facet::synthetic::lying_can(random);
    Scene scene;
    scene.solids.push_back({can, 1});
    scene.object_count = 1;
    const Vec3 axis(can.rotation(0, 2), can.rotation(1, 2), can.rotation(2, 2));
    EXPECT_NEAR(axis[2], 0.0, 1e-12);
    const Vec3 across(-axis[1], axis[0], 0.0);
    const double length = can.half_size[2];
    for (const double along : {-0.99, -0.5, 0.0, 0.5, 0.99}) {
      for (const double height : {1e-4, -1e-4}) {
        const Vec3 foot = can.centre + along * length * axis;
        const Ray ray{Vec3(foot[0], foot[1], height) - 0.5 * across, across};
        const bool hit = facet::synthetic::first_hit(scene, ray, 0.0, 10.0).has_value();
        EXPECT_EQ(hit, height > 0.0) << "at " << along << " of the half length, height " << height;
      }
    }
    // Its top is one diameter above the table.
    EXPECT_NEAR(drop(scene, can.centre[0], can.centre[1]).first, 2.0 * can.half_size[0], 1e-9);
  }
}

// Objects on the flat objects of on_flat and office stand exactly on their tops and inside them.
TEST(SyntheticHardCase, ObjectsOnFlatObjectsRestOnTheirTops) {
  for (const std::string& preset : {std::string("on_flat"), std::string("office")}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      SCOPED_TRACE(preset + " seed " + std::to_string(seed));
      RandomStream random(seed);
      const Scene scene = facet::synthetic::layout_scene(preset, {}, random);
      int on_flat = 0;
      for (const auto& item : scene.solids) {
        if (item.label == 0) continue;
        const double bottom =
            item.solid.centre[2] -
            (item.solid.shape == Shape::sphere ? item.solid.half_size[0] : item.solid.half_size[2]);
        if (std::abs(bottom) < 1e-12) continue;
        for (const auto& base : scene.solids) {
          if (base.label == 0 || &base == &item) continue;
          const double top = base.solid.centre[2] + base.solid.half_size[2];
          const bool flat = 2.0 * base.solid.half_size[2] <= 0.04 + 1e-12 &&
                            (base.solid.shape == Shape::box || base.solid.shape == Shape::cylinder);
          if (!flat || std::abs(top - bottom) > 1e-12) continue;
          if (facet::synthetic::rests_inside(base.solid, item.solid)) ++on_flat;
        }
      }
      EXPECT_GE(on_flat, preset == "on_flat" ? 2 : 1);
    }
  }
}

int count_shape(const Scene& scene, Shape shape) {
  return static_cast<int>(std::count_if(scene.solids.begin(), scene.solids.end(), [&](auto& s) {
    return s.label != 0 && s.solid.shape == shape;
  }));
}

TEST(SyntheticHardCase, PresetsHoldTheirKinds) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    RandomStream random(seed);
    const Scene office = facet::synthetic::layout_scene("office", {}, random);
    EXPECT_GE(count_shape(office, Shape::cup), 1);
    EXPECT_GE(count_shape(office, Shape::bowl), 1);
    int lying = 0;
    int tall = 0;
    int flat = 0;
    for (const auto& item : office.solids) {
      if (item.label == 0) continue;
      const Solid& s = item.solid;
      if (s.shape == Shape::cylinder && std::abs(s.rotation(2, 2)) < 0.5) ++lying;
      if (s.shape == Shape::box && 2.0 * s.half_size[2] >= 0.24) ++tall;
      if (s.shape == Shape::box && 2.0 * s.half_size[2] <= 0.04 &&
          2.0 * std::max(s.half_size[0], s.half_size[1]) >= 0.14)
        ++flat;
    }
    EXPECT_GE(lying, 1);
    EXPECT_GE(tall, 1);
    EXPECT_GE(flat, 2) << "a book and a magazine";
    const Scene containers = facet::synthetic::layout_scene("containers", {}, random);
    EXPECT_GE(count_shape(containers, Shape::cup), 2);
    EXPECT_GE(count_shape(containers, Shape::bowl), 2);
    EXPECT_GE(count_shape(containers, Shape::box), 2);
    const Scene pile = facet::synthetic::layout_scene("pile20", {}, random);
    int stacked = 0;
    for (const auto& item : pile.solids) {
      const Solid& s = item.solid;
      const double half_height = s.shape == Shape::sphere ? s.half_size[0] : s.half_size[2];
      if (item.label != 0 && s.centre[2] - half_height > 1e-9) ++stacked;
    }
    // Two stacks of two and three, and at least one object on a flat one.
    EXPECT_GE(stacked, 4);
    EXPECT_GE(count_shape(pile, Shape::cup) + count_shape(pile, Shape::bowl), 2);
  }
}

// Through the stage: the promised number of objects, every one of them seen, the same frames
// for a seed and other frames for another seed.
TEST(SyntheticHardCase, PresetsShowEveryObjectAndRepeatForASeed) {
  for (const std::string& preset : kHardPresets) {
    const auto range = facet::synthetic::preset_object_range(preset);
    for (std::int64_t seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE(preset + " seed " + std::to_string(seed));
      ParamMap params{{"preset", preset}, {"seed", seed}, {"scene", std::string("new")}};
      const auto frames = generate(params, 2);
      ASSERT_EQ(frames.size(), 2u);
      for (const auto& frame : frames) {
        EXPECT_GE(frame.labels.count, range.min);
        EXPECT_LE(frame.labels.count, range.max);
        const auto counts = label_pixels(frame.labels.labels);
        EXPECT_EQ(static_cast<int>(counts.size()), frame.labels.count);
        for (const auto& [id, pixels] : counts)
          EXPECT_GE(pixels, 50) << "object " << id;
      }
      const auto again = generate(params, 1);
      EXPECT_TRUE(same_image(again[0].depth.depth, frames[0].depth.depth));
      EXPECT_TRUE(same_image(again[0].labels.labels, frames[0].labels.labels));
      params["seed"] = seed + 100;
      const auto other = generate(params, 1);
      EXPECT_FALSE(same_image(other[0].labels.labels, frames[0].labels.labels));
    }
  }
}

TEST(SyntheticHardCase, RandomCameraStaysInItsRangesAndCoversThem) {
  facet::synthetic::ViewOptions options;
  options.random_camera = true;
  options.height_min_m = 0.6;
  options.height_max_m = 1.8;
  options.tilt_min_deg = 30.0;
  options.tilt_max_deg = 70.0;
  RandomStream random(11);
  double lowest = 10, highest = 0, flattest = 90, steepest = 0;
  for (int i = 0; i < 300; ++i) {
    const auto view =
        facet::synthetic::make_view(options, {525, 525, 319.5, 239.5, 640, 480}, random);
    ASSERT_GE(view.camera_height_m, 0.6 - 1e-9);
    ASSERT_LE(view.camera_height_m, 1.8 + 1e-9);
    ASSERT_GE(view.camera_tilt_deg, 30.0);
    ASSERT_LE(view.camera_tilt_deg, 70.0);
    // The rig really stands that high and looks down that steeply at the look-at point.
    EXPECT_NEAR(view.rig.position[2], view.camera_height_m, 1e-12);
    const Vec3 forward = view.rig.rotation * Vec3(0, 0, 1);
    EXPECT_NEAR(std::asin(-forward[2]) * 180.0 / std::numbers::pi, view.camera_tilt_deg, 1e-9);
    EXPECT_NEAR(view.rig.position[0] + forward[0] * view.rig.position[2] / -forward[2], 0.0, 1e-9);
    lowest = std::min(lowest, view.camera_height_m);
    highest = std::max(highest, view.camera_height_m);
    flattest = std::min(flattest, view.camera_tilt_deg);
    steepest = std::max(steepest, view.camera_tilt_deg);
  }
  EXPECT_LT(lowest, 0.7);
  EXPECT_GT(highest, 1.7);
  EXPECT_LT(flattest, 33.0);
  EXPECT_GT(steepest, 67.0);
}

// A drawn view through the stage: the metrics report a camera pose in the ranges, different for
// different layouts, and every object of the preset is still measured somewhere (no object out
// of the sensor's range or wholly in a projector shadow).
TEST(SyntheticHardCase, RandomCameraFramesShowTheObjects) {
  ParamMap params{{"preset", std::string("office")},     {"seed", std::int64_t{8}},
                  {"scene", std::string("new")},         {"camera", std::string("random")},
                  {"table_edge", std::string("random")}, {"wall_placement", std::string("random")}};
  facet::test::SyntheticRunner runner(params);
  std::vector<double> heights;
  for (int i = 0; i < 5; ++i) {
    runner.run();
    double height = -1, tilt = -1;
    for (const auto& metric : runner.metrics()) {
      if (metric.name == "camera_height_m") height = metric.value;
      if (metric.name == "camera_tilt_deg") tilt = metric.value;
    }
    EXPECT_GE(height, 0.6 - 1e-9);
    EXPECT_LE(height, 1.8 + 1e-9);
    EXPECT_GE(tilt, 30.0);
    EXPECT_LE(tilt, 70.0);
    heights.push_back(height);
    const auto& labels = runner.output<facet::LabelImage>("labels");
    EXPECT_EQ(static_cast<int>(label_pixels(labels.labels).size()), labels.count);
  }
  std::sort(heights.begin(), heights.end());
  EXPECT_GT(heights.back() - heights.front(), 0.05) << "the camera did not move";
}

// The horizontal distance from the camera (tilted `tilt_deg` down) of what the middle pixel of
// row v sees.
double horizontal_distance(const facet::DepthImage& depth, int v, double tilt_deg) {
  const double tilt = tilt_deg * std::numbers::pi / 180.0;
  const double z = depth.depth.at<std::uint16_t>(v, 320) * 0.001;
  const double y = (v - depth.camera.cy) * z / depth.camera.fy;
  return z * std::cos(tilt) - y * std::sin(tilt);
}

TEST(SyntheticHardCase, WallStandsAtTheGivenDistanceFromTheCamera) {
  // At 50 deg the top row meets the floor 3 m away; at 35 deg it looks over 10 m.
  for (const auto& [distance_m, tilt_deg] :
       {std::pair{1.5, 50.0}, std::pair{2.5, 50.0}, std::pair{3.5, 35.0}, std::pair{4.0, 35.0}}) {
    SCOPED_TRACE("wall at " + std::to_string(distance_m));
    ParamMap params{{"preset", std::string("separated3")},
                    {"noise", false},
                    {"camera_tilt_deg", tilt_deg},
                    {"wall_placement", std::string("camera")},
                    {"wall_camera_distance_m", distance_m}};
    const auto frame = generate(params, 1).at(0);
    // The top rows look past the table: at the wall.
    for (const int v : {0, 10, 20}) {
      EXPECT_NEAR(horizontal_distance(frame.depth, v, tilt_deg), distance_m, 0.002) << "row " << v;
    }
  }
  facet::synthetic::ViewOptions options;
  options.wall = facet::synthetic::WallPlacement::random;
  RandomStream random(5);
  int walls = 0;
  for (int i = 0; i < 200; ++i) {
    const auto view =
        facet::synthetic::make_view(options, {525, 525, 319.5, 239.5, 640, 480}, random);
    if (!view.room.wall) {
      EXPECT_EQ(view.wall_from_camera_m, 0.0);
      continue;
    }
    ++walls;
    EXPECT_GE(view.wall_from_camera_m, 1.5 - 1e-9);
    EXPECT_LE(view.wall_from_camera_m, 4.0 + 1e-9);
    EXPECT_NEAR(view.room.wall_distance_m - view.rig.position[1], view.wall_from_camera_m, 1e-12);
  }
  EXPECT_GT(walls, 120);
  EXPECT_LT(walls, 185);
}

// Height above the table top of what pixel (u, v) measured, for the default camera.
double height_above_table(const facet::DepthImage& depth, int u, int v) {
  const double tilt = 50.0 * std::numbers::pi / 180.0;
  const double z = depth.depth.at<std::uint16_t>(v, u) * 0.001;
  const double y = (v - depth.camera.cy) * z / depth.camera.fy;
  return 0.95 * std::sin(tilt) - y * std::cos(tilt) - z * std::sin(tilt);
}

TEST(SyntheticHardCase, TableEdgeInViewShowsItsFrontFaceAndTheFloor) {
  for (const std::string edge : {"in_view", "hidden"}) {
    SCOPED_TRACE(edge);
    ParamMap params{{"preset", std::string("containers")}, {"noise", false}, {"table_edge", edge}};
    const auto frame = generate(params, 1).at(0);
    int face_px = 0;
    int floor_px = 0;
    for (int v = 240; v < 480; ++v) {
      for (int u = 0; u < 640; ++u) {
        if (frame.depth.depth.at<std::uint16_t>(v, u) == 0) continue;
        const double height = height_above_table(frame.depth, u, v);
        if (height < -0.004 && height > -0.026) ++face_px;
        if (std::abs(height + 0.72) < 0.005) ++floor_px;
      }
    }
    if (edge == "in_view") {
      EXPECT_GT(face_px, 640) << "the 3 cm front face spans the image";
      EXPECT_GT(floor_px, 20000);
    } else {
      EXPECT_EQ(face_px, 0);
      EXPECT_EQ(floor_px, 0);
    }
    EXPECT_EQ(static_cast<int>(label_pixels(frame.labels.labels).size()), frame.labels.count);
  }
}

}  // namespace
