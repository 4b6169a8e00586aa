#include "facet/algo/plane.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace facet::algo {
namespace {

Eigen::Vector3f point_at(std::span<const float> xyz, std::size_t i) {
  return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
}

}  // namespace

Plane Plane::through(const Eigen::Vector3f& unit_normal, const Eigen::Vector3f& point_m) {
  Plane plane{unit_normal, -unit_normal.dot(point_m)};
  if (plane.offset_m < 0.0F) {
    plane.normal = -plane.normal;
    plane.offset_m = -plane.offset_m;
  }
  return plane;
}

Eigen::Vector3d PlaneMoments::centroid_m() const {
  if (count_ == 0) return Eigen::Vector3d::Zero();
  return origin_m_ + sum_m_ / static_cast<double>(count_);
}

std::optional<Plane> PlaneMoments::plane() const {
  const std::optional<PlaneFrame> fitted = frame();
  if (!fitted) return std::nullopt;
  return fitted->plane;
}

std::optional<PlaneFrame> PlaneMoments::frame() const {
  if (count_ < 3) return std::nullopt;
  const double inverse = 1.0 / static_cast<double>(count_);
  const Eigen::Vector3d mean = sum_m_ * inverse;
  const Eigen::Matrix3d sum_sq_m2 = sum_sq_m2_.selfadjointView<Eigen::Upper>();
  const Eigen::Matrix3d covariance = sum_sq_m2 * inverse - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if (solver.info() != Eigen::Success) return std::nullopt;
  // Eigenvalues ascending: a plane needs spread in two directions.
  if (!(solver.eigenvalues()(1) > kMinSpread_m2)) return std::nullopt;
  Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
  const Eigen::Vector3d centroid = origin_m_ + mean;
  double offset = -normal.dot(centroid);
  if (offset < 0.0) {
    normal = -normal;
    offset = -offset;
  }
  PlaneFrame fitted;
  fitted.plane = Plane{normal.cast<float>(), static_cast<float>(offset)};
  fitted.axis_u = solver.eigenvectors().col(2).normalized().cast<float>();
  fitted.axis_v = normal.cross(solver.eigenvectors().col(2)).normalized().cast<float>();
  return fitted;
}

std::optional<Plane> least_squares_plane(std::span<const float> xyz) {
  PlaneMoments moments;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    moments.add(xyz[i], xyz[i + 1], xyz[i + 2]);
  return moments.plane();
}

int ransac_hypotheses_needed(double inlier_share, double confidence) {
  constexpr int kMany = 1 << 30;
  if (!(confidence > 0.0)) return 1;
  if (!(inlier_share > 0.0)) return kMany;
  const double all_inliers = std::pow(std::min(inlier_share, 1.0), 3.0);
  if (all_inliers >= 1.0) return 1;
  const double needed =
      std::log(1.0 - std::min(confidence, 1.0 - 1e-12)) / std::log(1.0 - all_inliers);
  return needed >= kMany ? kMany : std::max(1, static_cast<int>(std::ceil(needed)));
}

std::optional<Plane> ransac_plane(std::span<const float> xyz, const RansacPlaneRule& rule,
                                  std::mt19937& rng) {
  const std::size_t count = xyz.size() / 3;
  if (count < 3) return std::nullopt;
  std::uniform_int_distribution<std::size_t> pick(0, count - 1);
  // Hypotheses are scored on an evenly strided subset: a patch is one surface, so a few hundred
  // points judge a hypothesis as well as all of them.
  const std::size_t step = std::max<std::size_t>(
      1, count / static_cast<std::size_t>(std::max(1, rule.max_scored_points)));

  const std::size_t scored = (count + step - 1) / step;
  const bool adaptive = rule.confidence > 0.0 && rule.max_iterations > rule.iterations;
  int wanted = rule.iterations;

  std::optional<Plane> best;
  std::size_t best_support = 0;
  for (int iteration = 0; iteration < wanted; ++iteration) {
    const Eigen::Vector3f a = point_at(xyz, pick(rng));
    const Eigen::Vector3f b = point_at(xyz, pick(rng));
    const Eigen::Vector3f c = point_at(xyz, pick(rng));
    const Eigen::Vector3f cross = (b - a).cross(c - a);
    const float length = cross.norm();
    // Collinear or repeated samples: |cross| (twice the triangle's area) of 1 cm² at least.
    if (!(length > 1e-4F)) continue;
    const Plane hypothesis = Plane::through(cross / length, a);
    std::size_t support = 0;
    for (std::size_t i = 0; i < count; i += step) {
      if (std::abs(hypothesis.signed_distance_m(&xyz[3 * i])) <= rule.inlier_distance_m) {
        ++support;
      }
    }
    if (support > best_support) {
      best_support = support;
      best = hypothesis;
      if (adaptive) {
        const double share = static_cast<double>(support) / static_cast<double>(scored);
        wanted = std::clamp(ransac_hypotheses_needed(share, rule.confidence), rule.iterations,
                            rule.max_iterations);
      }
    }
  }
  if (!best) return std::nullopt;

  PlaneMoments inliers;
  for (std::size_t i = 0; i < count; ++i) {
    const float* p = &xyz[3 * i];
    if (std::abs(best->signed_distance_m(p)) <= rule.inlier_distance_m) {
      inliers.add(p[0], p[1], p[2]);
    }
  }
  if (auto refit = inliers.plane()) return refit;
  return best;
}

}  // namespace facet::algo
