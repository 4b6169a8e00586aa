#include "synthetic/layout_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "synthetic/shells.hpp"

namespace facet::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;

struct Placed {
  double x, y, radius;
};

// Whether the footprint of `upper` (box-like: half x, y at yaw) lies on the top of `base`.
bool footprint_on_top(const Solid& base, const Vec3& upper_centre, const Vec3& upper_half,
                      double upper_yaw) {
  const Mat3 to_base = base.rotation.t();
  const Mat3 upper_rotation = yaw_rotation(upper_yaw);
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      const Vec3 corner =
          upper_centre + upper_rotation * Vec3(sx * upper_half[0], sy * upper_half[1], 0.0);
      const Vec3 local = to_base * (corner - base.centre);
      if (std::abs(local[0]) > base.half_size[0] || std::abs(local[1]) > base.half_size[1])
        return false;
    }
  }
  return true;
}

// A box-like solid (box or rounded box) of at most `fraction` of the base's top, standing on it
// off-centre when it fits.
Solid stack_on(const Solid& base, RandomStream& random, bool rounded, double fraction) {
  const double base_yaw = std::atan2(base.rotation(1, 0), base.rotation(0, 0));
  const double top_z = base.centre[2] + base.half_size[2];
  const Vec3 half(base.half_size[0] * random.uniform(0.45, fraction),
                  base.half_size[1] * random.uniform(0.45, fraction), random.uniform(0.02, 0.05));
  double yaw = base_yaw;
  Vec3 centre(base.centre[0], base.centre[1], 0.0);
  for (int attempt = 0; attempt < 40; ++attempt) {
    const double try_yaw = base_yaw + random.uniform(-0.35, 0.35);
    const Vec3 shift = base.rotation * Vec3(random.uniform(-0.5, 0.5) * base.half_size[0],
                                            random.uniform(-0.5, 0.5) * base.half_size[1], 0.0);
    const Vec3 try_centre(base.centre[0] + shift[0], base.centre[1] + shift[1], 0.0);
    if (footprint_on_top(base, try_centre, half, try_yaw)) {
      yaw = try_yaw;
      centre = try_centre;
      break;
    }
  }
  if (!rounded) return box(centre[0], centre[1], top_z, half, yaw);
  return rounded_box(centre[0], centre[1], top_z, half, yaw,
                     std::min({half[0], half[1], half[2]}) * 0.4);
}

Solid stack_base(RandomStream& random) {
  const Vec3 half(random.uniform(0.055, 0.08), random.uniform(0.045, 0.07),
                  random.uniform(0.025, 0.055));
  return box(0, 0, 0, half, random_yaw(random));
}

}  // namespace

void Group::add(const Solid& solid, double footprint_radius) {
  members.push_back(solid);
  footprints.push_back(footprint_radius);
  const double reach = std::hypot(solid.centre[0], solid.centre[1]) + footprint_radius;
  radius = std::max(radius, reach);
}

void Group::recentre() {
  double x_min = 1e9, x_max = -1e9, y_min = 1e9, y_max = -1e9;
  for (std::size_t i = 0; i < members.size(); ++i) {
    x_min = std::min(x_min, members[i].centre[0] - footprints[i]);
    x_max = std::max(x_max, members[i].centre[0] + footprints[i]);
    y_min = std::min(y_min, members[i].centre[1] - footprints[i]);
    y_max = std::max(y_max, members[i].centre[1] + footprints[i]);
  }
  const double dx = 0.5 * (x_min + x_max);
  const double dy = 0.5 * (y_min + y_max);
  radius = 0.0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    members[i].centre[0] -= dx;
    members[i].centre[1] -= dy;
    radius =
        std::max(radius, std::hypot(members[i].centre[0], members[i].centre[1]) + footprints[i]);
  }
}

double footprint_radius(const Solid& solid) {
  switch (solid.shape) {
    case Shape::box:
    case Shape::rounded_box:
      return std::hypot(solid.half_size[0], solid.half_size[1]);
    case Shape::cylinder:
      // Upright: its radius; lying: the half diagonal of its silhouette from above.
      return solid.rotation(2, 2) > 0.5 ? solid.half_size[0]
                                        : std::hypot(solid.half_size[0], solid.half_size[2]);
    case Shape::sphere:
    case Shape::cup:
      return solid.half_size[0];
    case Shape::bowl:
      return bowl_rim_radius(solid.half_size[0], solid.half_size[2], solid.wall);
    case Shape::plane:
      break;
  }
  return 0.0;
}

// The makers place a solid resting on the horizontal surface at height `base_z`.
Solid box(double x, double y, double base_z, const Vec3& half, double yaw) {
  return Solid{Shape::box, Vec3(x, y, base_z + half[2]), yaw_rotation(yaw), half, 0.0};
}

Solid rounded_box(double x, double y, double base_z, const Vec3& half, double yaw,
                  double rounding) {
  return Solid{Shape::rounded_box, Vec3(x, y, base_z + half[2]), yaw_rotation(yaw), half, rounding};
}

Solid upright_cylinder(double x, double y, double base_z, double radius, double half_height) {
  return Solid{Shape::cylinder, Vec3(x, y, base_z + half_height), Mat3::eye(),
               Vec3(radius, radius, half_height), 0.0};
}

Solid lying_cylinder(double x, double y, double base_z, double radius, double half_length,
                     double yaw) {
  return Solid{Shape::cylinder, Vec3(x, y, base_z + radius), lying_rotation(yaw),
               Vec3(radius, radius, half_length), 0.0};
}

Solid sphere(double x, double y, double base_z, double radius) {
  return Solid{Shape::sphere, Vec3(x, y, base_z + radius), Mat3::eye(),
               Vec3(radius, radius, radius), 0.0};
}

Solid cup(double x, double y, double base_z, double radius, double half_height, double wall) {
  Solid solid{Shape::cup, Vec3(x, y, base_z + half_height), Mat3::eye(),
              Vec3(radius, radius, half_height), 0.0};
  solid.wall = wall;
  return solid;
}

Solid bowl(double x, double y, double base_z, double sphere_radius, double half_height,
           double wall) {
  Solid solid{Shape::bowl, Vec3(x, y, base_z + half_height), Mat3::eye(),
              Vec3(sphere_radius, sphere_radius, half_height), 0.0};
  solid.wall = wall;
  return solid;
}

double random_yaw(RandomStream& random) {
  return random.uniform(-kPi, kPi);
}

// Object sizes: `scale` 1 for the few-object presets, smaller for clutter.
Vec3 random_box_half(RandomStream& random, double scale) {
  return scale *
         Vec3(random.uniform(0.03, 0.07), random.uniform(0.03, 0.06), random.uniform(0.025, 0.07));
}

// A single object of a random kind, resting on the table at the origin.
Solid random_object(RandomStream& random, double scale) {
  switch (random.uniform_int(0, 4)) {
    case 0:
      return box(0, 0, 0, random_box_half(random, scale), random_yaw(random));
    case 1: {
      const Vec3 half = random_box_half(random, scale);
      const double rounding = std::min({half[0], half[1], half[2]}) * random.uniform(0.25, 0.6);
      return rounded_box(0, 0, 0, half, random_yaw(random), rounding);
    }
    case 2:
      return upright_cylinder(0, 0, 0, scale * random.uniform(0.028, 0.05),
                              scale * random.uniform(0.04, 0.09));
    case 3:
      return lying_cylinder(0, 0, 0, scale * random.uniform(0.025, 0.04),
                            scale * random.uniform(0.05, 0.08), random_yaw(random));
    default:
      return sphere(0, 0, 0, scale * random.uniform(0.03, 0.055));
  }
}

Group single(const Solid& solid) {
  Group group;
  group.add(solid, footprint_radius(solid));
  return group;
}

// Two boxes side by side, sharing part of a face.
Group touching_boxes(RandomStream& random) {
  const double yaw = random_yaw(random);
  const Vec3 a = random_box_half(random, 1.0);
  const Vec3 b = random_box_half(random, 1.0);
  const double slide = random.uniform(-0.5, 0.5) * std::min(a[1], b[1]);
  const Mat3 r = yaw_rotation(yaw);
  const Vec3 offset = r * Vec3(a[0] + b[0], slide, 0.0);
  // Centred on the pair's midpoint.
  const Vec3 mid = 0.5 * offset;
  Group group;
  const Solid first = box(-mid[0], -mid[1], 0, a, yaw);
  const Solid second = box(offset[0] - mid[0], offset[1] - mid[1], 0, b, yaw);
  group.add(first, footprint_radius(first));
  group.add(second, footprint_radius(second));
  return group;
}

// A box and a round object (upright cylinder or sphere) touching one of its side faces.
Group box_and_round(RandomStream& random) {
  const double yaw = random_yaw(random);
  const Vec3 a = random_box_half(random, 1.0);
  const Mat3 r = yaw_rotation(yaw);
  const bool use_sphere = random.chance(0.4);
  // A sphere touches the face at its equator: the box must be at least that tall.
  const double radius =
      use_sphere ? std::min(random.uniform(0.03, 0.05), a[2]) : random.uniform(0.03, 0.05);
  const double slide = random.uniform(-0.6, 0.6) * a[1];
  const Vec3 offset = r * Vec3(a[0] + radius, slide, 0.0);
  const Vec3 mid = 0.5 * offset;
  Group group;
  const Solid first = box(-mid[0], -mid[1], 0, a, yaw);
  const Solid second = use_sphere ? sphere(offset[0] - mid[0], offset[1] - mid[1], 0, radius)
                                  : upright_cylinder(offset[0] - mid[0], offset[1] - mid[1], 0,
                                                     radius, random.uniform(0.04, 0.09));
  group.add(first, footprint_radius(first));
  group.add(second, footprint_radius(second));
  return group;
}

// `levels` objects stacked on a box (the top one a box, a rounded box or an upright cylinder).
Group stack(RandomStream& random, int levels) {
  Group group;
  Solid base = stack_base(random);
  group.add(base, footprint_radius(base));
  for (int level = 1; level < levels; ++level) {
    const bool top = level == levels - 1;
    const int kind = top ? random.uniform_int(0, 2) : 0;
    Solid upper;
    if (kind == 2) {
      const double radius =
          std::min(base.half_size[0], base.half_size[1]) * random.uniform(0.5, 0.8);
      upper = upright_cylinder(base.centre[0], base.centre[1], base.centre[2] + base.half_size[2],
                               radius, random.uniform(0.03, 0.07));
    } else {
      upper = stack_on(base, random, kind == 1, 0.85);
    }
    group.add(upper, footprint_radius(upper));
    base = upper;
  }
  return group;
}

// A tall box behind and a lower object in front of it (nearer the camera, which looks along +y),
// shifted sideways so that it hides part of the tall one.
Group occluding_pair(RandomStream& random) {
  const Vec3 back_half(random.uniform(0.035, 0.06), random.uniform(0.03, 0.05),
                       random.uniform(0.07, 0.1));
  const Solid back = box(0, 0, 0, back_half, random.uniform(-0.4, 0.4));
  Solid front = random_object(random, 0.9);
  // Keep the front object lower than the back one, so that the back one shows above it.
  if (front.centre[2] + front.half_size[2] > 0.7 * 2.0 * back_half[2]) {
    front = upright_cylinder(0, 0, 0, random.uniform(0.03, 0.045), back_half[2] * 0.6);
  }
  const double gap = random.uniform(0.015, 0.04);
  const double front_y = -(footprint_radius(back) + footprint_radius(front) + gap);
  const double side =
      (random.chance(0.5) ? 1.0 : -1.0) * random.uniform(0.3, 0.7) * footprint_radius(back);
  front.centre[0] += side;
  front.centre[1] += front_y;
  Group group;
  group.add(back, footprint_radius(back));
  group.add(front, footprint_radius(front));
  group.recentre();
  return group;
}

// Places the groups by rejection sampling: no two bounding circles closer than `gap`.
std::vector<Solid> place(const std::vector<Group>& groups, const Area& area, double gap,
                         RandomStream& random) {
  std::vector<Placed> placed;
  std::vector<Solid> solids;
  for (const Group& group : groups) {
    bool done = false;
    for (int attempt = 0; attempt < 2000 && !done; ++attempt) {
      const double x_low = area.x_min + group.radius;
      const double x_high = area.x_max - group.radius;
      const double y_low = area.y_min + group.radius;
      const double y_high = area.y_max - group.radius;
      if (x_low > x_high || y_low > y_high) break;
      const double x = random.uniform(x_low, x_high);
      const double y = random.uniform(y_low, y_high);
      const bool free = std::all_of(placed.begin(), placed.end(), [&](const Placed& other) {
        return std::hypot(x - other.x, y - other.y) >= group.radius + other.radius + gap;
      });
      if (!free) continue;
      placed.push_back({x, y, group.radius});
      for (Solid solid : group.members) {
        solid.centre[0] += x;
        solid.centre[1] += y;
        solids.push_back(solid);
      }
      done = true;
    }
    if (!done) {
      throw std::runtime_error("no room on the table for all objects of the preset");
    }
  }
  return solids;
}

}  // namespace facet::synthetic
