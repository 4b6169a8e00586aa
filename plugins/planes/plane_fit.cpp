#include "planes/plane_fit.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace facet::planes {
namespace {

Eigen::Vector3f point_at(std::span<const float> points, std::size_t i) {
  return {points[3 * i], points[3 * i + 1], points[3 * i + 2]};
}

// Normal towards the camera: the camera centre (origin) is on the positive side, n·0 + d > 0.
PlaneModel oriented(Eigen::Vector3f normal, const Eigen::Vector3f& on_plane) {
  float offset = -normal.dot(on_plane);
  if (offset < 0.0F) {
    normal = -normal;
    offset = -offset;
  }
  return {normal, offset};
}

}  // namespace

std::optional<PlaneModel> least_squares_plane(std::span<const float> points) {
  const std::size_t count = points.size() / 3;
  if (count < 3) return std::nullopt;
  // Accumulate in double: centimetre-scale spreads at metre-scale coordinates lose precision in
  // float sums of squares.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_sq = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d p = point_at(points, i).cast<double>();
    sum += p;
    sum_sq.noalias() += p * p.transpose();
  }
  const Eigen::Vector3d mean = sum / static_cast<double>(count);
  const Eigen::Matrix3d covariance = sum_sq / static_cast<double>(count) - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if (solver.info() != Eigen::Success) return std::nullopt;
  // Eigenvalues ascending: a plane needs spread in two directions.
  if (!(solver.eigenvalues()(1) > 1e-10)) return std::nullopt;
  const Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
  return oriented(normal.cast<float>(), mean.cast<float>());
}

std::optional<PlaneModel> fit_plane(std::span<const float> points, const PlaneFitRule& rule,
                                    std::mt19937& rng) {
  const std::size_t count = points.size() / 3;
  if (count < 3) return std::nullopt;
  std::uniform_int_distribution<std::size_t> pick(0, count - 1);
  // Hypotheses are scored on an evenly strided subset: a patch is one surface, so a few hundred
  // points judge a hypothesis as well as all of them.
  const std::size_t step = std::max<std::size_t>(
      1, count / static_cast<std::size_t>(std::max(1, rule.max_scored_points)));

  std::optional<PlaneModel> best;
  std::size_t best_support = 0;
  for (int iteration = 0; iteration < rule.ransac_iterations; ++iteration) {
    const Eigen::Vector3f a = point_at(points, pick(rng));
    const Eigen::Vector3f b = point_at(points, pick(rng));
    const Eigen::Vector3f c = point_at(points, pick(rng));
    const Eigen::Vector3f cross = (b - a).cross(c - a);
    const float length = cross.norm();
    // Collinear or repeated samples: a 1 cm triangle at least (|cross| = twice its area).
    if (!(length > 1e-4F)) continue;
    const PlaneModel hypothesis = oriented(cross / length, a);
    std::size_t support = 0;
    for (std::size_t i = 0; i < count; i += step) {
      if (std::abs(hypothesis.signed_distance_m(&points[3 * i])) <= rule.inlier_distance_m) {
        ++support;
      }
    }
    if (support > best_support) {
      best_support = support;
      best = hypothesis;
    }
  }
  if (!best) return std::nullopt;

  std::vector<float> inliers;
  inliers.reserve(points.size());
  for (std::size_t i = 0; i < count; ++i) {
    if (std::abs(best->signed_distance_m(&points[3 * i])) <= rule.inlier_distance_m) {
      inliers.insert(inliers.end(), &points[3 * i], &points[3 * i] + 3);
    }
  }
  if (auto refit = least_squares_plane(inliers)) return refit;
  return best;
}

}  // namespace facet::planes
