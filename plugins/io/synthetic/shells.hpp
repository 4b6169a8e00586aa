#pragma once
// Open containers as exact solids: a cup (a cylinder shell with a bottom) and a bowl (a
// spherical shell cut flat at the rim and at the foot). Both are constructive solids: the ray's
// span inside each basic solid (sphere, infinite cylinder, horizontal slab) is computed in
// closed form, the spans are intersected and subtracted, and the first boundary crossed is the
// hit. So the inside of a container is seen through its open top, exactly, with no tracing.
//
// Local frame: z up along the axis, the origin half way between the bottom and the rim.

#include <optional>

#include "synthetic/primitives.hpp"

namespace facet::synthetic {

// Cup: outer radius `radius`, height 2 * `half_height`; side wall and bottom both `wall` thick.
std::optional<RayHit> hit_cup(const Vec3& origin, const Vec3& direction, double radius,
                              double half_height, double wall, double t_min, double t_max);

// Bowl: the shell between the spheres of radius `sphere_radius` and `sphere_radius` - `wall`
// around the point (0, 0, bowl_sphere_centre_z(...)), cut by the planes z = -half_height (the
// flat foot, which stands on the table) and z = +half_height (the rim, at or below the sphere
// centre, so the bowl is widest at its rim). The foot cuts the outer sphere only: the bottom is
// wall / 2 thick.
std::optional<RayHit> hit_bowl(const Vec3& origin, const Vec3& direction, double sphere_radius,
                               double half_height, double wall, double t_min, double t_max);

// Height of the bowl's sphere centre in its local frame: the foot plane cuts the outer sphere
// wall / 2 below the inner sphere's lowest point.
double bowl_sphere_centre_z(double sphere_radius, double half_height, double wall);
// Outer radius of the bowl's rim, its widest horizontal extent.
double bowl_rim_radius(double sphere_radius, double half_height, double wall);
// Radius of the flat foot the bowl stands on.
double bowl_foot_radius(double sphere_radius, double wall);

}  // namespace facet::synthetic
