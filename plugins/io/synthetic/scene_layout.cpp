#include "synthetic/scene_layout.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "synthetic/hard_presets.hpp"
#include "synthetic/layout_parts.hpp"

namespace facet::synthetic {
namespace {

void add_room(Scene& scene, const RoomOptions& room) {
  double table_far_y = room.table_far_y_m;
  if (room.wall) {
    table_far_y = room.table_reaches_wall ? room.wall_distance_m
                                          : std::min(room.wall_distance_m, room.table_far_y_m);
  }
  const double table_near_y = room.table_near_y_m;
  const double thickness = 0.03;
  const Vec3 table_half(0.8, 0.5 * (table_far_y - table_near_y), 0.5 * thickness);
  scene.solids.push_back(
      {Solid{Shape::box, Vec3(0.0, 0.5 * (table_far_y + table_near_y), -0.5 * thickness),
             Mat3::eye(), table_half, 0.0},
       0});
  scene.solids.push_back(
      {Solid{Shape::plane, Vec3(0, 0, -room.table_height_m), Mat3::eye(), Vec3(), 0.0}, 0});
  if (room.wall) {
    // Local z (the plane's normal) towards the camera: -y.
    const Mat3 facing_camera(1, 0, 0, 0, 0, -1, 0, 1, 0);
    scene.solids.push_back(
        {Solid{Shape::plane, Vec3(0, room.wall_distance_m, 0), facing_camera, Vec3(), 0.0}, 0});
  }
}

}  // namespace

const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> names = {"separated3", "touching_pairs", "stacked_occluded",
                                                 "clutter20",  "on_flat",        "pile20",
                                                 "office",     "containers"};
  return names;
}

ObjectCount preset_object_range(const std::string& preset) {
  if (preset == "separated3") return {3, 3};
  if (preset == "touching_pairs") return {5, 5};
  if (preset == "stacked_occluded") return {9, 9};
  if (preset == "clutter20") return {20, 20};
  if (const auto range = hard_preset_object_range(preset)) return *range;
  throw std::invalid_argument("unknown preset '" + preset + "'");
}

int preset_object_count(const std::string& preset) {
  const ObjectCount range = preset_object_range(preset);
  if (range.min != range.max) {
    throw std::invalid_argument("preset '" + preset + "' draws a varying number of objects");
  }
  return range.min;
}

namespace {

// One draw of the preset's objects and their places; throws std::runtime_error when the groups
// drawn do not fit on the table together.
Scene try_layout(const std::string& preset, const RoomOptions& room, RandomStream& random) {
  std::vector<Group> groups;
  Area area{-0.3, 0.3, -0.2, 0.25};
  double gap = 0.06;
  if (preset == "separated3") {
    groups.push_back(single(box(0, 0, 0, random_box_half(random, 1.0), random_yaw(random))));
    groups.push_back(
        single(upright_cylinder(0, 0, 0, random.uniform(0.03, 0.05), random.uniform(0.05, 0.09))));
    if (random.chance(0.5)) {
      groups.push_back(single(sphere(0, 0, 0, random.uniform(0.035, 0.055))));
    } else {
      const Vec3 half = random_box_half(random, 1.0);
      groups.push_back(single(rounded_box(0, 0, 0, half, random_yaw(random),
                                          0.5 * std::min({half[0], half[1], half[2]}))));
    }
    gap = 0.08;
  } else if (preset == "touching_pairs") {
    groups.push_back(touching_boxes(random));
    groups.push_back(box_and_round(random));
    groups.push_back(single(random_object(random, 1.0)));
    area = {-0.38, 0.38, -0.24, 0.32};
    gap = 0.05;
  } else if (preset == "stacked_occluded") {
    groups.push_back(stack(random, 2));
    groups.push_back(stack(random, 3));
    groups.push_back(stack(random, 2));
    groups.push_back(occluding_pair(random));
    area = {-0.4, 0.4, -0.25, 0.35};
    gap = 0.04;
  } else if (preset == "clutter20") {
    for (int i = 0; i < 20; ++i)
      groups.push_back(single(random_object(random, 0.7)));
    area = {-0.4, 0.4, -0.24, 0.34};
    gap = 0.02;
  } else if (auto hard = draw_hard_preset(preset, random)) {
    groups = std::move(hard->groups);
    area = hard->area;
    gap = hard->gap;
  } else {
    throw std::invalid_argument("unknown preset '" + preset + "'");
  }
  if (room.wall) area.y_max = std::min(area.y_max, room.wall_distance_m - 0.02);
  // Objects keep off the table's front edge (which may be in view) and its back edge.
  area.y_min = std::max(area.y_min, room.table_near_y_m + 0.03);
  if (!room.wall || !room.table_reaches_wall)
    area.y_max = std::min(area.y_max, room.table_far_y_m - 0.03);

  Scene scene;
  add_room(scene, room);
  int label = 0;
  for (const Solid& solid : place(groups, area, gap, random))
    scene.solids.push_back({solid, ++label});
  scene.object_count = label;
  return scene;
}

}  // namespace

Scene layout_scene(const std::string& preset, const RoomOptions& room, RandomStream& random) {
  preset_object_range(preset);  // throws for an unknown preset
  // Objects too large to fit together are drawn again (a few percent of the draws).
  constexpr int kDraws = 20;
  for (int draw = 1;; ++draw) {
    try {
      return try_layout(preset, room, random);
    } catch (const std::runtime_error&) {
      if (draw == kDraws) throw;
    }
  }
}

}  // namespace facet::synthetic
