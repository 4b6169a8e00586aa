#pragma once
// The analytic solids a synthetic scene is made of, and where a ray first meets each of them.
// World frame: metres, z up, the table top at z = 0.

#include <opencv2/core/matx.hpp>
#include <optional>

namespace facet::synthetic {

using Vec3 = cv::Vec3d;
using Mat3 = cv::Matx33d;

struct Ray {
  Vec3 origin;
  Vec3 direction;  // not necessarily unit length: hits are reported in units of it
};

struct RayHit {
  double t = 0.0;  // origin + t * direction is the surface point
  Vec3 normal;     // unit, outward
};

enum class Shape {
  box,          // half_size = half extents along the local axes
  rounded_box,  // half_size as a box, edges and corners rounded with `rounding`
  cylinder,     // local z is the axis: radius half_size[0], half length half_size[2]
  sphere,       // radius half_size[0]
  plane,        // infinite plane through `centre` with local z as its normal
  cup,          // open cylinder shell with a bottom: outer radius half_size[0], half height
                // half_size[2], side and bottom `wall` thick (shells.hpp)
  bowl,         // spherical shell of radius half_size[0] cut flat at foot and rim, half height
                // half_size[2], `wall` thick (shells.hpp)
};

// A solid placed in the world: local coordinates p_local = rotation^T * (p_world - centre).
struct Solid {
  Shape shape = Shape::box;
  Vec3 centre;
  Mat3 rotation = Mat3::eye();  // local to world
  Vec3 half_size;
  double rounding = 0.0;  // rounded_box only
  double wall = 0.0;      // cup and bowl only: thickness of the shell

  // Radius of a sphere around `centre` enclosing the solid (infinite for a plane).
  double bounding_radius() const;
  // The first hit with t in (t_min, t_max), if any.
  std::optional<RayHit> intersect(const Ray& ray, double t_min, double t_max) const;
};

// Rotation about the world z axis by `yaw_rad`.
Mat3 yaw_rotation(double yaw_rad);
// A local frame whose z axis is horizontal at heading `yaw_rad` (for a cylinder lying down).
Mat3 lying_rotation(double yaw_rad);

}  // namespace facet::synthetic
