#include "partition/segment_plane.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace facet::partition {

void Bounds::add(float x, float y, float z) {
  if (empty) {
    min_m = {x, y, z};
    max_m = {x, y, z};
    empty = false;
    return;
  }
  min_m = {std::min(min_m[0], x), std::min(min_m[1], y), std::min(min_m[2], z)};
  max_m = {std::max(max_m[0], x), std::max(max_m[1], y), std::max(max_m[2], z)};
}

void Bounds::merge(const Bounds& other) {
  if (other.empty) return;
  add(other.min_m[0], other.min_m[1], other.min_m[2]);
  add(other.max_m[0], other.max_m[1], other.max_m[2]);
}

FittedPlane fit_plane(const BlobSegments& points, std::int32_t begin, std::int32_t end) {
  FittedPlane plane;
  const std::int32_t n = end - begin;
  if (n < 3) return plane;
  // Sums relative to the first point keep the covariance free of cancellation at 1 m range.
  const auto b = static_cast<std::size_t>(begin);
  const double ox = points.x[b];
  const double oy = points.y[b];
  const double oz = points.z[b];
  double sx = 0, sy = 0, sz = 0, sxx = 0, sxy = 0, sxz = 0, syy = 0, syz = 0, szz = 0;
  for (auto k = b; k < static_cast<std::size_t>(end); ++k) {
    const double dx = points.x[k] - ox;
    const double dy = points.y[k] - oy;
    const double dz = points.z[k] - oz;
    sx += dx;
    sy += dy;
    sz += dz;
    sxx += dx * dx;
    sxy += dx * dy;
    sxz += dx * dz;
    syy += dy * dy;
    syz += dy * dz;
    szz += dz * dz;
  }
  const double inv = 1.0 / n;
  const Eigen::Vector3d mean(sx * inv, sy * inv, sz * inv);
  Eigen::Matrix3d cov;
  cov << sxx * inv, sxy * inv, sxz * inv, sxy * inv, syy * inv, syz * inv, sxz * inv, syz * inv,
      szz * inv;
  cov -= mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov);
  // Collinear points (a one-pixel-wide strip) leave the normal undetermined.
  if (solver.eigenvalues()(1) <= 1e-12) return plane;
  Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
  const Eigen::Vector3d centroid = mean + Eigen::Vector3d(ox, oy, oz);
  if (normal.dot(centroid) > 0.0) normal = -normal;
  plane.normal = {static_cast<float>(normal.x()), static_cast<float>(normal.y()),
                  static_cast<float>(normal.z())};
  plane.offset_m = static_cast<float>(-normal.dot(centroid));
  plane.centroid_m = {static_cast<float>(centroid.x()), static_cast<float>(centroid.y()),
                      static_cast<float>(centroid.z())};
  plane.valid = true;
  return plane;
}

Bounds bounds_of(const BlobSegments& points, std::int32_t begin, std::int32_t end) {
  Bounds box;
  for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k) {
    box.add(points.x[k], points.y[k], points.z[k]);
  }
  return box;
}

double share_not_in_front(const BlobSegments& points, const FittedPlane& plane, std::int32_t begin,
                          std::int32_t end, double tolerance_m) {
  if (end <= begin) return 1.0;
  const float nx = plane.normal[0];
  const float ny = plane.normal[1];
  const float nz = plane.normal[2];
  const float d0 = plane.offset_m;
  const auto tol = static_cast<float>(tolerance_m);
  const float* x = points.x.data();
  const float* y = points.y.data();
  const float* z = points.z.data();
  std::int32_t in_front = 0;
  for (std::int32_t k = begin; k < end; ++k) {
    in_front += static_cast<std::int32_t>(nx * x[k] + ny * y[k] + nz * z[k] + d0 > tol);
  }
  return 1.0 - static_cast<double>(in_front) / static_cast<double>(end - begin);
}

double plane_rms_m(const BlobSegments& points, const FittedPlane& plane, std::int32_t begin,
                   std::int32_t end) {
  if (end <= begin) return 0.0;
  double sum = 0.0;
  for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k) {
    const double d = plane.signed_distance_m(points.x[k], points.y[k], points.z[k]);
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(end - begin));
}

double normal_cosine(const FittedPlane& a, const FittedPlane& b) {
  return static_cast<double>(a.normal[0] * b.normal[0] + a.normal[1] * b.normal[1] +
                             a.normal[2] * b.normal[2]);
}

}  // namespace facet::partition
