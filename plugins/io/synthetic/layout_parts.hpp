#pragma once
// The building blocks of the presets' layouts: solids resting on a surface, groups of objects
// that stand together (stacks, touching pairs), and their placement on the table without
// overlap. World frame: metres, z up, the table top at z = 0.

#include <vector>

#include "synthetic/primitives.hpp"
#include "synthetic/random_stream.hpp"

namespace facet::synthetic {

// Where on the table objects go, around the camera's look-at point (world x and y).
struct Area {
  double x_min, x_max, y_min, y_max;
};

// One or more objects that stand together, built around the origin and moved to their place
// as a unit.
struct Group {
  std::vector<Solid> members;
  std::vector<double> footprints;  // radius of each member's extent in the table plane
  double radius = 0.0;             // bounding circle in the table plane, around the origin

  void add(const Solid& solid, double footprint_radius);
  // Moves the group so that the middle of its footprints' extent is the origin, which keeps
  // the bounding circle of a lopsided group (an occluding pair) small.
  void recentre();
};

// Radius of a circle around the solid's centre that holds its extent in the table plane.
double footprint_radius(const Solid& solid);

// The makers place a solid resting on the horizontal surface at height `base_z`.
Solid box(double x, double y, double base_z, const Vec3& half, double yaw);
Solid rounded_box(double x, double y, double base_z, const Vec3& half, double yaw, double rounding);
Solid upright_cylinder(double x, double y, double base_z, double radius, double half_height);
Solid lying_cylinder(double x, double y, double base_z, double radius, double half_length,
                     double yaw);
Solid sphere(double x, double y, double base_z, double radius);
Solid cup(double x, double y, double base_z, double radius, double half_height, double wall);
Solid bowl(double x, double y, double base_z, double sphere_radius, double half_height,
           double wall);

double random_yaw(RandomStream& random);
// Box half extents; `scale` 1 for the few-object presets, smaller for clutter.
Vec3 random_box_half(RandomStream& random, double scale);
// A single object of a random kind (box, rounded box, upright or lying cylinder, sphere),
// resting on the table at the origin.
Solid random_object(RandomStream& random, double scale);

Group single(const Solid& solid);
// `levels` objects stacked on a box (the top one a box, a rounded box or an upright cylinder).
Group stack(RandomStream& random, int levels);
// Two boxes side by side, sharing part of a face.
Group touching_boxes(RandomStream& random);
// A box and a round object (upright cylinder or sphere) touching one of its side faces.
Group box_and_round(RandomStream& random);
// A tall box behind and a lower object in front of it, hiding part of it from the camera.
Group occluding_pair(RandomStream& random);

// Places the groups by rejection sampling: no two bounding circles closer than `gap`. Throws
// std::runtime_error when a group finds no room.
std::vector<Solid> place(const std::vector<Group>& groups, const Area& area, double gap,
                         RandomStream& random);

}  // namespace facet::synthetic
