#pragma once
// Levenberg–Marquardt fit of a superquadric to an object's visible points, over size, shape and
// pose together, with an optional support-plane contact term for the side the camera cannot see.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "facet/algo/levenberg_marquardt.hpp"
#include "facet/types/geometry.hpp"

namespace facet::shape {

struct SuperquadricFitOptions {
  int max_points = 200;            // random subsample of the object's points used by the fit
  std::uint64_t seed = 1;          // subsample seed (mixed with the object id by the caller)
  algo::SolverOptions solver;      // iterations, tolerances and damping of the minimisation
  double support_weight = 1.0;     // contact term weight, relative to all points together
  double size_prior_weight = 0.1;  // pull of the log sizes towards the initial box (see .cpp)
  double initial_epsilon = 0.5;
};

struct SuperquadricFit {
  Superquadric superquadric;    // valid = false when there were too few points
  algo::SolverSummary summary;  // costs, iterations and why the minimisation stopped
  int points_used = 0;
};

// Fits from `initial` (an oriented box: pose and half extents become pose and a1..a3). With a
// support plane the fit also pulls the superquadric's lowest point onto the plane; a weak prior
// keeps sizes that the points do not constrain (the unseen back) near the initial box. Needs at
// least 2 × 11 points; fewer give an invalid result. The residual is the RMS radial distance
// (metres).
SuperquadricFit fit_superquadric(const std::vector<Eigen::Vector3d>& points_m,
                                 const OrientedBox& initial, const Plane* support,
                                 const SuperquadricFitOptions& options);

// Up to `count` of the points, drawn without replacement by a seeded generator (all of them, in
// order, when there are not more than `count`). Same seed, same points, on every platform.
std::vector<Eigen::Vector3d> subsample_points(const std::vector<Eigen::Vector3d>& points_m,
                                              int count, std::uint64_t seed);

}  // namespace facet::shape
