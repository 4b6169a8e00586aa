#pragma once
// Fitting one plane to the points of a surface patch: a few RANSAC hypotheses from random point
// triples, then a least-squares refit to the inliers of the best one (paper sec. II-B d).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <random>
#include <span>

namespace facet::planes {

// A plane n·x + d = 0, unit normal oriented towards the camera (d > 0 for planes not through the
// camera centre).
struct PlaneModel {
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  float offset_m = 0.0F;

  float signed_distance_m(const float* xyz) const {
    return normal.x() * xyz[0] + normal.y() * xyz[1] + normal.z() * xyz[2] + offset_m;
  }
};

struct PlaneFitRule {
  int ransac_iterations = 20;
  float inlier_distance_m = 0.006F;  // RANSAC and refit threshold (the paper's delta / 2)
  int max_scored_points = 1000;      // hypotheses are scored on at most this many patch points
};

// points: the patch's points, three floats each (metres, all finite). Returns nothing when the
// patch is degenerate (fewer than 3 points, all triples collinear, no support for any
// hypothesis). The random generator is advanced; the caller seeds it.
std::optional<PlaneModel> fit_plane(std::span<const float> points, const PlaneFitRule& rule,
                                    std::mt19937& rng);

// Least-squares plane (smallest eigenvector of the covariance) through the given points,
// oriented towards the camera; nothing for fewer than 3 points or a degenerate (line) spread.
std::optional<PlaneModel> least_squares_plane(std::span<const float> points);

}  // namespace facet::planes
