#include "shape/pca_box.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace facet::shape {
namespace {

// The box spanned by the points' extent along the columns of `axes` (orthonormal, right-handed).
OrientedBox box_along_axes(const std::vector<Eigen::Vector3d>& points_m,
                           const Eigen::Matrix3d& axes) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (const Eigen::Vector3d& p : points_m) {
    const Eigen::Vector3d local = axes.transpose() * p;
    low = low.cwiseMin(local);
    high = high.cwiseMax(local);
  }
  OrientedBox box;
  box.pose.linear() = axes;
  box.pose.translation() = axes * (0.5 * (low + high));
  box.half_extents_m = 0.5 * (high - low);
  return box;
}

}  // namespace

OrientedBox fit_pca_box(const std::vector<Eigen::Vector3d>& points_m) {
  if (points_m.empty()) return {};
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points_m)
    mean += p;
  mean /= static_cast<double>(points_m.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points_m)
    covariance += (p - mean) * (p - mean).transpose();
  // Eigenvalues come in increasing order; the box's x axis is the direction of largest spread.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Eigen::Matrix3d axes;
  axes.col(0) = solver.eigenvectors().col(2);
  axes.col(1) = solver.eigenvectors().col(1);
  axes.col(2) = axes.col(0).cross(axes.col(1));
  return box_along_axes(points_m, axes);
}

namespace {

// Distance of a point, already in the box's frame, to the surface of a box of `half_extents_m`.
double distance_in_box_frame_m(const Eigen::Vector3d& local,
                               const Eigen::Vector3d& half_extents_m) {
  const Eigen::Vector3d outside = (local.cwiseAbs() - half_extents_m).cwiseMax(0.0);
  if (outside.squaredNorm() > 0.0) return outside.norm();
  return (half_extents_m - local.cwiseAbs()).minCoeff();
}

}  // namespace

double distance_to_box_surface_m(const OrientedBox& box, const Eigen::Vector3d& point_m) {
  return distance_in_box_frame_m(box.pose.inverse() * point_m, box.half_extents_m);
}

double box_surface_rms_m(const OrientedBox& box, const std::vector<Eigen::Vector3d>& points_m) {
  if (points_m.empty()) return 0.0;
  // The pose is inverted once here, not once per point.
  const Eigen::Matrix3d to_local = box.pose.linear().transpose();
  const Eigen::Vector3d origin = box.pose.translation();
  double sum_sq = 0.0;
  for (const Eigen::Vector3d& p : points_m) {
    const double d = distance_in_box_frame_m(to_local * (p - origin), box.half_extents_m);
    sum_sq += d * d;
  }
  return std::sqrt(sum_sq / static_cast<double>(points_m.size()));
}

OrientedBox fit_supported_box(const std::vector<Eigen::Vector3d>& points_m, const Plane& plane) {
  if (points_m.empty()) return {};
  const Eigen::Vector3d up = plane.normal.normalized();
  // Any in-plane basis, then 2D PCA of the points' shadow on the plane.
  const Eigen::Vector3d seed_axis =
      std::abs(up.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = (seed_axis - up * up.dot(seed_axis)).normalized();
  const Eigen::Vector3d e2 = up.cross(e1);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector3d& p : points_m)
    mean += Eigen::Vector2d(e1.dot(p), e2.dot(p));
  mean /= static_cast<double>(points_m.size());
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector3d& p : points_m) {
    const Eigen::Vector2d q = Eigen::Vector2d(e1.dot(p), e2.dot(p)) - mean;
    covariance += q * q.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(covariance);
  const Eigen::Vector2d major = solver.eigenvectors().col(1);
  Eigen::Matrix3d axes;
  axes.col(0) = major.x() * e1 + major.y() * e2;
  axes.col(2) = up;
  axes.col(1) = up.cross(axes.col(0));
  OrientedBox box = box_along_axes(points_m, axes);
  // Bottom on the plane: the box spans heights 0 .. the highest point above the plane.
  const Eigen::Vector3d centre_local = axes.transpose() * box.pose.translation();
  const double top_m =
      std::max(plane.signed_distance_m(box.pose.translation()) + box.half_extents_m.z(), 1e-4);
  const double centre_height_m = 0.5 * top_m;
  // Signed distance is up·x + d, so the height h sits at up·x = h - d.
  Eigen::Vector3d centre_new = centre_local;
  centre_new.z() = centre_height_m - plane.offset_m;
  box.pose.translation() = axes * centre_new;
  box.half_extents_m.z() = centre_height_m;
  return box;
}

OrientedBox extend_box_away_from_camera(const OrientedBox& box) {
  const Eigen::Vector3d centre = box.pose.translation();
  if (centre.norm() <= 0.0) return box;
  const Eigen::Vector3d view = centre.normalized();
  const Eigen::Matrix3d axes = box.pose.linear();
  int depth_axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(axes.col(k).dot(view)) > std::abs(axes.col(depth_axis).dot(view))) depth_axis = k;
  }
  double other_min_m = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (k != depth_axis) other_min_m = std::min(other_min_m, box.half_extents_m[k]);
  }
  OrientedBox out = box;
  const double grow_m = other_min_m - box.half_extents_m[depth_axis];
  if (grow_m <= 0.0) return out;
  out.half_extents_m[depth_axis] = other_min_m;
  // Shift the centre by the growth, away from the camera, so the visible front face stays put.
  Eigen::Vector3d away = axes.col(depth_axis);
  if (away.dot(view) < 0.0) away = -away;
  out.pose.translation() = centre + grow_m * away;
  return out;
}

}  // namespace facet::shape
