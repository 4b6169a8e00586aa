#pragma once
// Convex hulls of points on a floor plan (two coordinates across world up), for the table's
// outline and the scene model's test of whether one level lies over another.

#include <Eigen/Core>
#include <vector>

namespace facet::planes {

// Andrew's monotone chain: the hull's vertices counter-clockwise, no collinear ones. Empty when
// the points span no area (fewer than three distinct, or all on one line).
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points);

// Whether `point` lies inside `hull` (counter-clockwise, as convex_hull gives it) or on its
// border. False for an empty hull.
bool inside_convex_hull(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector2d& point);

}  // namespace facet::planes
