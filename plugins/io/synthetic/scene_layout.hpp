#pragma once
// The presets: which objects stand where on the table, drawn from a seeded random stream.
// Objects rest on the table or on each other (flat faces on flat tops) and never interpenetrate;
// objects of a touching pair share a face or a line exactly.

#include <string>
#include <vector>

#include "synthetic/random_stream.hpp"
#include "synthetic/scene.hpp"

namespace facet::synthetic {

// The preset names, in order of increasing complexity (the levels of the paper's Table II).
const std::vector<std::string>& preset_names();

// How many objects a preset places: the classic presets a fixed number, the hard-case presets
// (on_flat, pile20, office, containers) a number drawn per layout in [min, max].
struct ObjectCount {
  int min = 0;
  int max = 0;
};
ObjectCount preset_object_range(const std::string& preset);
// The fixed number of a classic preset; throws std::invalid_argument for a varying one.
int preset_object_count(const std::string& preset);

struct RoomOptions {
  double table_height_m = 0.72;    // table top above the floor
  bool wall = false;               // a wall behind the table
  double wall_distance_m = 0.45;   // world y of the wall: from the look-at point along +y
  bool table_reaches_wall = true;  // the table ends at the wall; else at table_far_y_m or it
  double table_near_y_m = -0.6;    // world y of the table's front edge
  double table_far_y_m = 0.6;      // world y of its back edge when no wall ends it
};

// The table (3 cm thick), floor and wall (label 0) and the preset's objects (labels 1..N), placed
// around the world origin (the camera's look-at point). Throws std::invalid_argument for an unknown
// preset and std::runtime_error when 20 draws of its objects found no room on the table for them
// all.
Scene layout_scene(const std::string& preset, const RoomOptions& room, RandomStream& random);

}  // namespace facet::synthetic
