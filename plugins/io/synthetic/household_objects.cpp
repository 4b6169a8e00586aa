#include "synthetic/household_objects.hpp"

#include <algorithm>
#include <cmath>

#include "synthetic/shells.hpp"

namespace facet::synthetic {
namespace {

bool upright_round(const Solid& solid) {
  return (solid.shape == Shape::cylinder || solid.shape == Shape::cup) &&
         solid.rotation(2, 2) > 0.5;
}

// Whether the point (world x, y) lies inside the top of `base`, `margin` from its border.
bool point_on_top(const Solid& base, const Vec3& point, double margin) {
  const Vec3 local = base.rotation.t() * (point - base.centre);
  if (upright_round(base)) return std::hypot(local[0], local[1]) <= base.half_size[0] - margin;
  return std::abs(local[0]) <= base.half_size[0] - margin &&
         std::abs(local[1]) <= base.half_size[1] - margin;
}

// An object small enough for a top whose smaller half extent is `room`, standing on the
// surface at `base_z` at (x, y).
Solid item_for(double room, double x, double y, double base_z, RandomStream& random) {
  const double reach = std::min(0.05, 0.7 * room);
  switch (random.uniform_int(0, 4)) {
    case 0: {
      const double side = random.uniform(0.6, 1.0) * reach / std::sqrt(2.0);
      const Vec3 half(side, side * random.uniform(0.6, 1.0), random.uniform(0.02, 0.05));
      return box(x, y, base_z, half, random_yaw(random));
    }
    case 1: {
      const double radius = std::min(random.uniform(0.035, 0.045), reach);
      return cup(x, y, base_z, radius, random.uniform(0.04, 0.055), random.uniform(0.003, 0.005));
    }
    case 2:
      return upright_cylinder(x, y, base_z, random.uniform(0.6, 1.0) * reach,
                              random.uniform(0.03, 0.07));
    case 3:
      return sphere(x, y, base_z, random.uniform(0.6, 1.0) * std::min(reach, 0.045));
    default: {
      // A small bowl: its rim may overhang the top, its foot stands on it.
      const double sphere_radius = random.uniform(0.04, 0.06);
      const double wall = 0.004;
      const double half_height = 0.5 * random.uniform(0.5, 0.7) * sphere_radius;
      return bowl(x, y, base_z, sphere_radius, half_height, wall);
    }
  }
}

}  // namespace

Solid book(RandomStream& random) {
  const double half_x = random.uniform(0.07, 0.15);
  const double half_y = random.uniform(0.05, std::min(0.11, half_x));
  return box(0, 0, 0, Vec3(half_x, half_y, 0.5 * random.uniform(0.015, 0.04)), random_yaw(random));
}

Solid magazine(RandomStream& random) {
  const Vec3 half(random.uniform(0.1, 0.15), random.uniform(0.075, 0.105),
                  0.5 * random.uniform(0.008, 0.012));
  return box(0, 0, 0, half, random_yaw(random));
}

Solid tray(RandomStream& random) {
  const Vec3 half(random.uniform(0.12, 0.15), random.uniform(0.08, 0.12),
                  0.5 * random.uniform(0.02, 0.03));
  return box(0, 0, 0, half, random_yaw(random));
}

Solid flat_tin(RandomStream& random) {
  return upright_cylinder(0, 0, 0, random.uniform(0.05, 0.1), 0.5 * random.uniform(0.01, 0.04));
}

Solid flat_object(RandomStream& random) {
  switch (random.uniform_int(0, 3)) {
    case 0:
      return book(random);
    case 1:
      return magazine(random);
    case 2:
      return tray(random);
    default:
      return flat_tin(random);
  }
}

Solid random_cup(RandomStream& random) {
  return cup(0, 0, 0, random.uniform(0.035, 0.045), random.uniform(0.04, 0.055),
             random.uniform(0.003, 0.005));
}

Solid random_bowl(RandomStream& random, double scale) {
  // The rim lies 0.2-0.5 sphere radii below the sphere centre, so its radius is 0.87-0.98 of
  // the sphere radius: a sphere radius of 6.2-10 cm gives rims of 11-20 cm across.
  const double sphere_radius = scale * random.uniform(0.062, 0.1);
  const double wall = random.uniform(0.004, 0.006);
  const double half_height = 0.5 * random.uniform(0.5, 0.8) * (sphere_radius - 0.5 * wall);
  return bowl(0, 0, 0, sphere_radius, half_height, wall);
}

Solid cereal_box(RandomStream& random) {
  const Vec3 half(random.uniform(0.08, 0.1), random.uniform(0.025, 0.04),
                  random.uniform(0.12, 0.16));
  return box(0, 0, 0, half, random_yaw(random));
}

Solid lying_can(RandomStream& random) {
  return lying_cylinder(0, 0, 0, random.uniform(0.025, 0.04), random.uniform(0.06, 0.1),
                        random_yaw(random));
}

bool rests_inside(const Solid& base, const Solid& item) {
  switch (item.shape) {
    case Shape::box:
    case Shape::rounded_box: {
      const Mat3 rotation = item.rotation;
      for (const double sx : {-1.0, 1.0}) {
        for (const double sy : {-1.0, 1.0}) {
          const Vec3 corner =
              item.centre + rotation * Vec3(sx * item.half_size[0], sy * item.half_size[1], 0.0);
          if (!point_on_top(base, corner, 0.0)) return false;
        }
      }
      return true;
    }
    case Shape::cylinder:
      if (item.rotation(2, 2) < 0.5) {
        // Lying: the line it touches the top along.
        const Vec3 axis(item.rotation(0, 2), item.rotation(1, 2), 0.0);
        return point_on_top(base, item.centre + item.half_size[2] * axis, 0.0) &&
               point_on_top(base, item.centre - item.half_size[2] * axis, 0.0);
      }
      return point_on_top(base, item.centre, item.half_size[0]);
    case Shape::cup:
      return point_on_top(base, item.centre, item.half_size[0]);
    case Shape::bowl:
      return point_on_top(base, item.centre, bowl_foot_radius(item.half_size[0], item.wall));
    case Shape::sphere:
      return point_on_top(base, item.centre, 0.0);
    case Shape::plane:
      break;
  }
  return false;
}

Group flat_with_items(const Solid& flat, int items, RandomStream& random) {
  Group group;
  group.add(flat, footprint_radius(flat));
  const double top_z = flat.centre[2] + flat.half_size[2];
  const double room =
      upright_round(flat) ? flat.half_size[0] : std::min(flat.half_size[0], flat.half_size[1]);
  struct Standing {
    double x, y, radius;
  };
  std::vector<Standing> standing;
  for (int item = 0; item < items; ++item) {
    bool placed = false;
    for (int attempt = 0; attempt < 60 && !placed; ++attempt) {
      // The first item falls back to the centre of the top, where it always fits.
      const bool centre = item == 0 && attempt == 59;
      const Vec3 offset =
          centre ? Vec3(0, 0, 0)
                 : flat.rotation * Vec3(random.uniform(-1.0, 1.0) * flat.half_size[0],
                                        random.uniform(-1.0, 1.0) * flat.half_size[1], 0.0);
      const Solid solid =
          item_for(room, flat.centre[0] + offset[0], flat.centre[1] + offset[1], top_z, random);
      if (!rests_inside(flat, solid)) continue;
      // 1 cm between the items' extents, so that none touches or overlaps another.
      const double radius = footprint_radius(solid);
      const bool apart = std::all_of(standing.begin(), standing.end(), [&](const Standing& s) {
        return std::hypot(solid.centre[0] - s.x, solid.centre[1] - s.y) >= radius + s.radius + 0.01;
      });
      if (!apart) continue;
      standing.push_back({solid.centre[0], solid.centre[1], radius});
      group.add(solid, radius);
      placed = true;
    }
  }
  return group;
}

}  // namespace facet::synthetic
