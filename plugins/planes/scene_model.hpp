#pragma once
// The scene model's first decision: which horizontal candidate plane is the table the objects
// stand on, and which horizontal planes are the flat tops of objects lying on it (docs/planes.md,
// "The scene model").
//
// Size alone does not tell a table from a book: on a crowded table the objects cut the table
// into many patches, and the largest horizontal patch may be a book, a tray or a box lying flat.
// So the horizontal candidates are first grouped into levels (candidates whose centroids lie
// within level_tolerance_m of one another's plane: the fragments of one table top), and levels
// are compared by their summed size and by their height along world up:
//   - the largest level is the table, unless
//   - a level lies more than max_object_height_m above it and holds large_view_fraction of the
//     view: then the largest level is the floor and that level the table seen above it; or
//   - a level lies below it by less than max_object_height_m, holds min_table_fraction of the
//     view and lies under it (min_table_under_share of the largest level's points, seen from
//     above, fall inside the lower level's convex outline): then the largest level is the top of
//     something standing on that lower table (a board, a big box lying flat) and the lower level
//     is the table (repeated downwards). A chair's seat beside a low table, a centimetre lower,
//     is not under it.
// Levels above the table by up to max_object_height_m are object tops: never support planes.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "facet/algo/plane.hpp"

namespace facet::planes {

struct TableRule {
  double min_cos_horizontal = 0.985;    // cos(alpha_z): a normal this close to up is horizontal
  float level_tolerance_m = 0.006F;     // centroids this close to a plane are on its level
  float max_object_height_m = 0.3F;     // a raised level up to this high is an object top
  double min_table_fraction = 0.05;     // a lower level this large (of the valid px) is the table
  double large_view_fraction = 0.15;    // a level this large far above the floor is the table
  double min_table_under_share = 0.25;  // of the upper level's points over the lower's outline
};

enum class CandidateRole : std::uint8_t {
  undecided,   // the support rule decides (walls, the floor, box faces)
  table,       // on the table's level: a support plane
  object_top,  // a level raised above the table by up to max_object_height_m: an object
};

struct TableChoice {
  int table = -1;                    // candidate index of the table's plane, -1 = no table
  std::vector<CandidateRole> roles;  // per candidate
  std::vector<float> height_m;       // per horizontal candidate: its level above the table
};

// candidates, their centroids (camera frame, metres), sizes (pixels) and footprints (a sample of
// their points) in the order of planes.support (largest first); `up` is world up (unit);
// valid_px the frame's valid pixels.
TableChoice choose_table(const std::vector<algo::Plane>& candidates,
                         const std::vector<Eigen::Vector3f>& centroids_m,
                         const std::vector<std::int64_t>& sizes_px,
                         const std::vector<std::vector<Eigen::Vector3f>>& footprints_m,
                         std::int64_t valid_px, const Eigen::Vector3f& up, const TableRule& rule);

// The share of `upper`'s points that, seen along `up` (unit), fall inside the convex hull of
// `lower`'s points; 0 when `lower` spans no area or `upper` is empty.
double share_over(const std::vector<Eigen::Vector3f>& upper_m,
                  const std::vector<Eigen::Vector3f>& lower_m, const Eigen::Vector3f& up);

}  // namespace facet::planes
