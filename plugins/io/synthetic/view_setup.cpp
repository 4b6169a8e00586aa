#include "synthetic/view_setup.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace facet::synthetic {
namespace {

// The front edge in view lies this fraction of the way from the nearest table point in view to
// the look-at point: far enough into the image that its 3 cm front face and the floor below it
// show, near enough to leave the objects' area on the table.
constexpr double kEdgeFraction = 0.3;
// A hidden front edge lies this far in front of the nearest table point in view.
constexpr double kHiddenEdgeMargin_m = 0.05;
// The front edge of the classic table (world y), kept whenever the view does not reach it.
constexpr double kClassicNearEdge_m = -0.6;
constexpr double kWallChance = 0.75;
// A drawn wall stands at least this far beyond the look-at point, behind the objects.
constexpr double kWallBehindLookAt_m = 0.45;

}  // namespace

bool view_is_drawn(const ViewOptions& options) {
  return options.random_camera || options.table_edge == TableEdge::random ||
         options.wall == WallPlacement::random;
}

double nearest_table_y_in_view(const CameraRig& rig) {
  const Ray ray = rig.pixel_ray(rig.intrinsics.cx, rig.intrinsics.height - 1.0);
  if (ray.direction[2] > -1e-9) return -1e9;
  const double t = -ray.origin[2] / ray.direction[2];
  return ray.origin[1] + t * ray.direction[1];
}

View make_view(const ViewOptions& options, const CameraIntrinsics& intrinsics,
               RandomStream& random) {
  View view;
  view.room = options.room;
  double distance_m = options.camera_distance_m;
  view.camera_tilt_deg = options.camera_tilt_deg;
  if (options.random_camera) {
    view.camera_height_m = random.uniform(options.height_min_m, options.height_max_m);
    view.camera_tilt_deg = random.uniform(options.tilt_min_deg, options.tilt_max_deg);
    distance_m = view.camera_height_m / std::sin(view.camera_tilt_deg * std::numbers::pi / 180.0);
  }
  view.rig = CameraRig::looking_at(intrinsics, Vec3(0, 0, 0), distance_m, view.camera_tilt_deg,
                                   options.projector_offset_m);
  view.camera_height_m = view.rig.position[2];

  const double edge_draw = options.table_edge == TableEdge::random ? random.uniform() : 1.0;
  view.table_edge_in_view = options.table_edge == TableEdge::in_view ||
                            (options.table_edge == TableEdge::random && edge_draw < 0.5);
  const double nearest_y = nearest_table_y_in_view(view.rig);
  if (view.table_edge_in_view) {
    view.room.table_near_y_m = (1.0 - kEdgeFraction) * nearest_y;
  } else {
    view.room.table_near_y_m = std::min(kClassicNearEdge_m, nearest_y - kHiddenEdgeMargin_m);
  }

  const double camera_y = view.rig.position[1];
  switch (options.wall) {
    case WallPlacement::fixed:
      break;
    case WallPlacement::camera:
      view.room.wall = true;
      view.room.table_reaches_wall = false;
      view.room.wall_distance_m = camera_y + options.wall_camera_distance_m;
      break;
    case WallPlacement::random: {
      const bool wall = random.chance(kWallChance);
      const double fraction = random.uniform();
      const double low = std::max(options.wall_camera_min_m, kWallBehindLookAt_m - camera_y);
      view.room.wall = wall && low <= options.wall_camera_max_m;
      view.room.table_reaches_wall = false;
      view.room.wall_distance_m = camera_y + low + fraction * (options.wall_camera_max_m - low);
      break;
    }
  }
  view.wall_from_camera_m = view.room.wall ? view.room.wall_distance_m - camera_y : 0.0;
  return view;
}

}  // namespace facet::synthetic
