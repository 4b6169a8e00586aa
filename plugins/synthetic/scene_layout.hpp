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

// How many objects a preset places.
int preset_object_count(const std::string& preset);

struct RoomOptions {
  double table_height_m = 0.72;   // table top above the floor
  bool wall = false;              // a wall behind the table
  double wall_distance_m = 0.45;  // from the camera's look-at point, along the view (+y)
};

// The table, floor and wall (label 0) and the preset's objects (labels 1..N), placed around the
// world origin (the camera's look-at point). Throws std::invalid_argument for an unknown preset
// and std::runtime_error when 20 draws of its objects found no room on the table for them all.
Scene layout_scene(const std::string& preset, const RoomOptions& room, RandomStream& random);

}  // namespace facet::synthetic
