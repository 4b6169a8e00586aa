#include "planes/scene_model.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "planes/convex_hull.hpp"

namespace facet::planes {
namespace {

struct Level {
  int seed = 0;  // its largest candidate, whose plane the others are measured against
  std::vector<int> members;
  std::int64_t size_px = 0;
};

// Horizontal candidates grouped into levels, largest candidate first; each level's seed is its
// largest member. A candidate joins the first level whose seed plane passes within tolerance of
// its centroid.
std::vector<Level> group_levels(const std::vector<algo::Plane>& candidates,
                                const std::vector<Eigen::Vector3f>& centroids_m,
                                const std::vector<std::int64_t>& sizes_px,
                                const Eigen::Vector3f& up, const TableRule& rule) {
  std::vector<int> horizontal;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].normal.dot(up) >= rule.min_cos_horizontal) {
      horizontal.push_back(static_cast<int>(i));
    }
  }
  std::stable_sort(horizontal.begin(), horizontal.end(),
                   [&](int a, int b) { return sizes_px[a] > sizes_px[b]; });
  std::vector<Level> levels;
  for (const int c : horizontal) {
    Level* home = nullptr;
    for (Level& level : levels) {
      const float height = candidates[level.seed].signed_distance_m(centroids_m[c].data());
      if (std::abs(height) <= rule.level_tolerance_m) {
        home = &level;
        break;
      }
    }
    if (home == nullptr) {
      levels.push_back(Level{c, {}, 0});
      home = &levels.back();
    }
    home->members.push_back(c);
    home->size_px += sizes_px[c];
  }
  return levels;
}

// The footprints of a level's members, together.
std::vector<Eigen::Vector3f> level_points(
    const Level& level, const std::vector<std::vector<Eigen::Vector3f>>& footprints_m) {
  std::vector<Eigen::Vector3f> points;
  for (const int c : level.members) {
    if (static_cast<std::size_t>(c) < footprints_m.size()) {
      points.insert(points.end(), footprints_m[c].begin(), footprints_m[c].end());
    }
  }
  return points;
}

}  // namespace

double share_over(const std::vector<Eigen::Vector3f>& upper_m,
                  const std::vector<Eigen::Vector3f>& lower_m, const Eigen::Vector3f& up) {
  if (upper_m.empty()) return 0.0;
  // Two axes across up: coordinates on the floor plan.
  const Eigen::Vector3d axis_u = up.cast<double>().unitOrthogonal();
  const Eigen::Vector3d axis_v = up.cast<double>().cross(axis_u);
  const auto plan = [&](const Eigen::Vector3f& p) {
    const Eigen::Vector3d q = p.cast<double>();
    return Eigen::Vector2d(q.dot(axis_u), q.dot(axis_v));
  };
  std::vector<Eigen::Vector2d> lower_plan;
  lower_plan.reserve(lower_m.size());
  for (const Eigen::Vector3f& p : lower_m)
    lower_plan.push_back(plan(p));
  const std::vector<Eigen::Vector2d> hull = convex_hull(std::move(lower_plan));
  if (hull.empty()) return 0.0;
  std::size_t inside = 0;
  for (const Eigen::Vector3f& p : upper_m) {
    if (inside_convex_hull(hull, plan(p))) ++inside;
  }
  return static_cast<double>(inside) / static_cast<double>(upper_m.size());
}

TableChoice choose_table(const std::vector<algo::Plane>& candidates,
                         const std::vector<Eigen::Vector3f>& centroids_m,
                         const std::vector<std::int64_t>& sizes_px,
                         const std::vector<std::vector<Eigen::Vector3f>>& footprints_m,
                         std::int64_t valid_px, const Eigen::Vector3f& up, const TableRule& rule) {
  TableChoice choice;
  choice.roles.assign(candidates.size(), CandidateRole::undecided);
  choice.height_m.assign(candidates.size(), 0.0F);
  const std::vector<Level> levels = group_levels(candidates, centroids_m, sizes_px, up, rule);
  if (levels.empty() || valid_px <= 0) return choice;

  // Height of `level` above `ref`: the distance of one seed's centroid from the other seed's
  // plane, taking the plane of the larger one. A small patch's plane can be tilted by a degree,
  // which at the centroid of a large level a metre away is more than a book's thickness.
  const auto height_above = [&](const Level& level, const Level& ref) {
    if (sizes_px[level.seed] > sizes_px[ref.seed]) {
      return -candidates[level.seed].signed_distance_m(centroids_m[ref.seed].data());
    }
    return candidates[ref.seed].signed_distance_m(centroids_m[level.seed].data());
  };
  const auto share = [&](const Level& level) {
    return static_cast<double>(level.size_px) / static_cast<double>(valid_px);
  };
  std::size_t table = 0;
  for (std::size_t i = 1; i < levels.size(); ++i) {
    if (levels[i].size_px > levels[table].size_px) table = i;
  }
  // A table seen above a dominant floor: the highest such level.
  float highest_m = rule.max_object_height_m;
  std::size_t above_floor = table;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const float height = height_above(levels[i], levels[table]);
    if (height > highest_m && share(levels[i]) >= rule.large_view_fraction) {
      highest_m = height;
      above_floor = i;
    }
  }
  table = above_floor;
  // The largest level may be something standing on the table: step down while a large enough
  // level lies a little below and under it. Each step goes down, so this ends.
  for (bool stepped = true; stepped;) {
    stepped = false;
    std::size_t lower = table;
    const std::vector<Eigen::Vector3f> upper_points = level_points(levels[table], footprints_m);
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const float height = height_above(levels[i], levels[table]);
      const bool just_below = height < -rule.level_tolerance_m &&
                              height >= -rule.max_object_height_m &&
                              share(levels[i]) >= rule.min_table_fraction;
      if (!just_below || (lower != table && levels[i].size_px <= levels[lower].size_px)) continue;
      // Beside it is not under it: a chair's seat behind a low table, a centimetre lower.
      if (share_over(upper_points, level_points(levels[i], footprints_m), up) <
          rule.min_table_under_share) {
        continue;
      }
      lower = i;
    }
    if (lower != table) {
      table = lower;
      stepped = true;
    }
  }

  choice.table = levels[table].seed;
  for (const Level& level : levels) {
    const float height = height_above(level, levels[table]);
    for (const int c : level.members)
      choice.height_m[c] = height;
    if (&level == &levels[table]) {
      for (const int c : level.members)
        choice.roles[c] = CandidateRole::table;
    } else if (height > rule.level_tolerance_m && height <= rule.max_object_height_m) {
      for (const int c : level.members)
        choice.roles[c] = CandidateRole::object_top;
    }
  }
  return choice;
}

}  // namespace facet::planes
