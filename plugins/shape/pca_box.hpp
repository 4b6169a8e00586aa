#pragma once
// Oriented boxes of point sets: the plain PCA box (what the paper compared superquadrics with),
// its fit residual, and the box extended to a support plane that initialises the superquadric.

#include <Eigen/Core>
#include <vector>

#include "facet/types/geometry.hpp"

namespace facet::shape {

// Axes = principal axes of the points' covariance, ordered by decreasing variance and made
// right-handed; the box is the tight min/max extent along them (so its centre is the extent's
// middle, not the centroid). Empty input gives a zero box at the origin.
OrientedBox fit_pca_box(const std::vector<Eigen::Vector3d>& points_m);

// Distance of a point to the box surface (inside: to the nearest face; outside: Euclidean).
double distance_to_box_surface_m(const OrientedBox& box, const Eigen::Vector3d& point_m);

// Root-mean-square distance of the points to the box surface; 0 for no points.
double box_surface_rms_m(const OrientedBox& box, const std::vector<Eigen::Vector3d>& points_m);

// A box whose z axis is the plane's normal and whose bottom lies on the plane: the points'
// shadow on the plane gives the footprint (PCA in the plane), their highest point the top. This
// is the "object stands on the table" model a depth camera cannot see but grasping needs.
OrientedBox fit_supported_box(const std::vector<Eigen::Vector3d>& points_m, const Plane& plane);

// Without a plane: the PCA box, with its axis most aligned with the viewing ray made at least as
// deep as the box's smaller other extent, grown away from the camera (the visible front stays
// where it is). A heuristic prior for the unseen back; documented in docs/shape.md.
OrientedBox extend_box_away_from_camera(const OrientedBox& box);

}  // namespace facet::shape
