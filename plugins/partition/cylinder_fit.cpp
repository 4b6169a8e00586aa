#include "partition/cylinder_fit.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace facet::partition {
namespace {

// Neighbours this many pixels away span a pixel's normal: far enough apart that a Kinect's 1 mm
// depth steps tilt it little, near enough to stay on a can 5 cm across at 2 m.
constexpr int kNormalStepPx = 3;
// Neighbours further apart than this along the depth lie across a depth step.
constexpr double kMaxNeighbourDepthStepM = 0.02;
// On a cylinder every normal is perpendicular to the axis: the weakest direction of the normals'
// scatter holds less than this share of it. Normals of a Kinect patch scatter by about 5–10°, a
// share of 0.01–0.03 in any direction.
constexpr double kMaxAxisShare = 0.06;
// The normals must turn about the axis by more than that noise: the middle direction of their
// scatter holds at least this share, as on an arc of 60° (0.09); a plane's noise gives 0.01–0.03.
constexpr double kMinTurnShare = 0.08;

bool has_point(const cv::Vec3f& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && p[2] > 0.0F;
}

Eigen::Vector3d as_vector(const cv::Vec3f& p) {
  return {p[0], p[1], p[2]};
}

// Σ n nᵀ / |set| of both sets, each weighted equally.
Eigen::Matrix3d normal_scatter(const OrientedSamples& a, const OrientedSamples& b) {
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto* set : {&a, &b}) {
    const double weight = 1.0 / static_cast<double>(set->normals.size());
    for (const Eigen::Vector3d& n : set->normals)
      scatter += weight * n * n.transpose();
  }
  return scatter;
}

struct Circle {
  Eigen::Vector2d centre;
  double radius = 0.0;
};

// The algebraic (Kåsa) circle through points projected onto the plane of `u` and `v`, each set
// weighted equally: x² + y² + D x + E y + F = 0 by least squares, in coordinates centred on the
// points (a can 4 cm across 0.8 m from the camera would otherwise make the system ill-posed).
bool fit_circle(const OrientedSamples& a, const OrientedSamples& b, const Eigen::Vector3d& u,
                const Eigen::Vector3d& v, Circle& circle) {
  const auto project = [&](const Eigen::Vector3d& p) {
    return Eigen::Vector2d(p.dot(u), p.dot(v));
  };
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto* set : {&a, &b}) {
    for (const Eigen::Vector3d& p : set->points)
      mean += project(p) / (2.0 * static_cast<double>(set->points.size()));
  }
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  for (const auto* set : {&a, &b}) {
    const double weight = 1.0 / static_cast<double>(set->points.size());
    for (const Eigen::Vector3d& p : set->points) {
      const Eigen::Vector2d q = project(p) - mean;
      const Eigen::Vector3d row(q.x(), q.y(), 1.0);
      normal += weight * row * row.transpose();
      right -= weight * q.squaredNorm() * row;
    }
  }
  const Eigen::Vector3d solution = normal.ldlt().solve(right);
  if (!solution.allFinite()) return false;
  const Eigen::Vector2d centre = -0.5 * solution.head<2>();
  const double squared = centre.squaredNorm() - solution(2);
  if (!(squared > 0.0)) return false;
  circle.centre = centre + mean;
  circle.radius = std::sqrt(squared);
  return true;
}

double share_on_cylinder(const OrientedSamples& set, const Eigen::Vector3d& u,
                         const Eigen::Vector3d& v, const Circle& circle, double tolerance_m) {
  std::size_t on = 0;
  for (const Eigen::Vector3d& p : set.points) {
    const Eigen::Vector2d q(p.dot(u), p.dot(v));
    if (std::abs((q - circle.centre).norm() - circle.radius) <= tolerance_m) ++on;
  }
  return static_cast<double>(on) / static_cast<double>(set.points.size());
}

}  // namespace

void take_oriented_samples(const BlobSegments& points, const Segment& segment,
                           const cv::Mat& point_image, std::int32_t max_samples,
                           OrientedSamples& out) {
  out.points.clear();
  out.normals.clear();
  const int width = point_image.cols;
  const int height = point_image.rows;
  const auto* image = point_image.ptr<cv::Vec3f>();
  const auto at = [&](int u, int v) -> const cv::Vec3f& {
    return image[static_cast<std::size_t>(v) * static_cast<std::size_t>(width) +
                 static_cast<std::size_t>(u)];
  };
  const std::int32_t stride = sample_stride(segment, max_samples);
  for (std::int32_t k = segment.begin; k < segment.end; k += stride) {
    const std::int32_t pixel = points.pixel[static_cast<std::size_t>(k)];
    const int u = pixel % width;
    const int v = pixel / width;
    if (u < kNormalStepPx || v < kNormalStepPx || u + kNormalStepPx >= width ||
        v + kNormalStepPx >= height) {
      continue;
    }
    const cv::Vec3f& left = at(u - kNormalStepPx, v);
    const cv::Vec3f& right = at(u + kNormalStepPx, v);
    const cv::Vec3f& up = at(u, v - kNormalStepPx);
    const cv::Vec3f& down = at(u, v + kNormalStepPx);
    if (!has_point(left) || !has_point(right) || !has_point(up) || !has_point(down)) continue;
    const Eigen::Vector3d along_row = as_vector(right) - as_vector(left);
    const Eigen::Vector3d along_column = as_vector(down) - as_vector(up);
    if (std::abs(along_row.z()) > kMaxNeighbourDepthStepM ||
        std::abs(along_column.z()) > kMaxNeighbourDepthStepM) {
      continue;
    }
    const Eigen::Vector3d normal = along_row.cross(along_column);
    const double length = normal.norm();
    if (!(length > 0.0)) continue;
    const auto i = static_cast<std::size_t>(k);
    out.points.emplace_back(points.x[i], points.y[i], points.z[i]);
    out.normals.push_back(normal / length);
  }
}

bool one_circular_cylinder(const OrientedSamples& a, const OrientedSamples& b,
                           const CylinderRule& rule) {
  if (a.points.size() < 10 || b.points.size() < 10) return false;
  // Eigenvalues ascending: the axis is the direction the normals do not point in.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> scatter(normal_scatter(a, b));
  if (scatter.info() != Eigen::Success) return false;
  const Eigen::Vector3d shares = scatter.eigenvalues() / scatter.eigenvalues().sum();
  if (shares(0) > kMaxAxisShare || shares(1) < kMinTurnShare) return false;
  const Eigen::Vector3d u = scatter.eigenvectors().col(1);
  const Eigen::Vector3d v = scatter.eigenvectors().col(2);

  Circle circle;
  if (!fit_circle(a, b, u, v, circle) || circle.radius > rule.max_radius_m) return false;
  return share_on_cylinder(a, u, v, circle, rule.tolerance_m) >= rule.min_share &&
         share_on_cylinder(b, u, v, circle, rule.tolerance_m) >= rule.min_share;
}

}  // namespace facet::partition
