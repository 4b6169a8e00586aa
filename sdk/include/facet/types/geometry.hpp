#pragma once
// Geometric results of the object stages: support planes and per-object shape models, in metres in
// the camera frame (x right, y down, z along the optical axis).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "facet/packet.hpp"
#include "facet/types/frame.hpp"

namespace facet {

// A plane n·x + d = 0 with unit normal n pointing towards the camera (n·x < 0 for points in front).
// What a support plane is in the scene (docs/planes.md, "The scene model"): the table the objects
// stand on, or structure around it that is background too.
enum class PlaneRole : std::int32_t {
  table,  // the support the objects stand on (at most one per frame)
  floor,  // horizontal, below the table
  wall,   // any other background plane: walls, a vertical face of the room
};

struct Plane {
  std::int32_t id = 0;  // 1..N, the id its pixels carry in the plane label image
  PlaneRole role = PlaneRole::wall;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset_m = 0.0;  // d
  std::int64_t inliers = 0;
  double rms_m = 0.0;       // root-mean-square point-to-plane distance of the inliers
  bool horizontal = false;  // normal within the stage's angle of world up (a table, a floor)

  double signed_distance_m(const Eigen::Vector3d& point_m) const {
    return normal.dot(point_m) + offset_m;
  }
};

struct SupportPlanes : FrameHeader {
  std::vector<Plane> planes;
  Eigen::Vector3d up = -Eigen::Vector3d::UnitY();  // world up in the camera frame, unit length
  std::int32_t table_id = 0;                       // id of the plane with role table, 0 = none
  // The table's visible extent: a convex polygon of points on the table plane (camera frame,
  // metres), counter-clockwise seen from above; empty without a table. Objects stand inside it.
  std::vector<Eigen::Vector3d> table_outline_m;

  const Plane* table() const {
    for (const Plane& plane : planes) {
      if (plane.id == table_id) return &plane;
    }
    return nullptr;
  }
};

// An oriented box: pose maps box coordinates to the camera frame; the box spans ±half_extents_m.
struct OrientedBox {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
  double residual_m = 0.0;  // RMS distance of the points it was fitted to from its surface
};

// Inside-outside function F(x) = ((|x|/a1)^(2/e2) + (|y|/a2)^(2/e2))^(e2/e1) + (|z|/a3)^(2/e1) in
// the superquadric's own frame; F = 1 on the surface.
struct Superquadric {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();  // a1, a2, a3 (half sizes)
  double epsilon1 = 1.0;  // shape along z: 0.1 square .. 1 round .. 2 pinched
  double epsilon2 = 1.0;  // shape in the xy plane
  double residual = 0.0;  // RMS of the fit's residual over the points used
  bool valid = false;
};

enum class GraspPrototype { none, power, precision, pincer };

struct ObjectModel {
  std::int32_t id = 0;  // the id its pixels carry in the object label image
  std::int64_t pixel_count = 0;
  Eigen::Vector3d centroid_m = Eigen::Vector3d::Zero();
  Eigen::AlignedBox3d bounds_m;    // axis-aligned, camera frame
  OrientedBox box;                 // oriented, from PCA of the points
  std::int32_t support_plane = 0;  // Plane::id it stands on, 0 = none
  // That plane's equation n·x + d = 0 as in Plane (unit normal towards the camera, d in metres),
  // so that a consumer of the list (a grasp planner) needs no SupportPlanes beside it. Zero normal
  // and offset when support_plane is 0.
  Eigen::Vector3d support_normal = Eigen::Vector3d::Zero();
  double support_offset_m = 0.0;
  Superquadric superquadric;
  GraspPrototype grasp = GraspPrototype::none;
};

struct ObjectList : FrameHeader {
  std::vector<ObjectModel> objects;
};

std::string_view to_string(GraspPrototype grasp) noexcept;

}  // namespace facet

FACET_TYPE_KEY(facet::SupportPlanes, "facet.SupportPlanes/1");
// /2: ObjectModel gained support_normal and support_offset_m.
FACET_TYPE_KEY(facet::ObjectList, "facet.ObjectList/2");
