#pragma once
// Where the camera stands and what of the room it sees, fixed by the parameters or drawn per
// layout: the camera's height and tilt, whether the table's front edge (and the floor below it)
// is in view, and whether and how far away a wall stands behind the table.

#include "facet/types/frame.hpp"
#include "synthetic/random_stream.hpp"
#include "synthetic/scene.hpp"
#include "synthetic/scene_layout.hpp"

namespace facet::synthetic {

enum class TableEdge { hidden, in_view, random };
enum class WallPlacement { fixed, camera, random };

struct ViewOptions {
  // fixed camera: this far from the look-at point (the world origin), this far below the
  // horizontal; random camera: height above the table and tilt drawn uniformly in the ranges.
  bool random_camera = false;
  double camera_distance_m = 0.95;
  double camera_tilt_deg = 50.0;
  double height_min_m = 0.6;
  double height_max_m = 1.8;
  double tilt_min_deg = 30.0;
  double tilt_max_deg = 70.0;
  double projector_offset_m = 0.075;

  TableEdge table_edge = TableEdge::hidden;
  // fixed: room.wall and room.wall_distance_m as given; camera: a wall wall_camera_distance_m
  // from the camera; random: a wall in three layouts of four, its distance from the camera
  // drawn in [wall_camera_min_m, wall_camera_max_m] (and at least 0.45 m beyond the look-at
  // point, behind the objects).
  WallPlacement wall = WallPlacement::fixed;
  double wall_camera_distance_m = 2.5;
  double wall_camera_min_m = 1.5;
  double wall_camera_max_m = 4.0;

  RoomOptions room;  // the table height, and the wall of WallPlacement::fixed
};

struct View {
  CameraRig rig;
  RoomOptions room;
  double camera_height_m = 0.0;     // camera centre above the table top
  double camera_tilt_deg = 0.0;     // optical axis below the horizontal
  double wall_from_camera_m = 0.0;  // horizontal distance from the camera to the wall; 0 = none
  bool table_edge_in_view = false;
};

// Whether any of the options is drawn per layout.
bool view_is_drawn(const ViewOptions& options);

// The view of one layout; `random` is read only for what the options draw, a fixed number of
// variates per call.
View make_view(const ViewOptions& options, const CameraIntrinsics& intrinsics,
               RandomStream& random);

// World y where the ray through the bottom row's middle pixel meets the table plane (z = 0): the
// nearest table point in view. Below -10 m when that ray does not go down.
double nearest_table_y_in_view(const CameraRig& rig);

}  // namespace facet::synthetic
