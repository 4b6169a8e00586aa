#include "normals/smallest_eigenvector.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

namespace facet::normals {

Eigen::Vector3d smallest_eigenvector(const Eigen::Matrix3d& cov) {
  const double a = cov(0, 0);
  const double b = cov(1, 1);
  const double c = cov(2, 2);
  const double d = cov(0, 1);
  const double e = cov(0, 2);
  const double f = cov(1, 2);
  // det(lambda I - cov) = lambda^3 - trace lambda^2 + minors lambda - det.
  const double trace = a + b + c;
  const double minors = a * b + a * c + b * c - d * d - e * e - f * f;
  const double det = a * (b * c - f * f) - d * (d * c - f * e) + e * (d * f - b * e);
  if (!(trace > 0.0)) return Eigen::Vector3d::UnitZ();  // all points equal: no direction

  double lambda = 0.0;
  const double tolerance = 1e-14 * trace;
  for (int i = 0; i < 64; ++i) {
    const double value = ((lambda - trace) * lambda + minors) * lambda - det;
    const double slope = (3.0 * lambda - 2.0 * trace) * lambda + minors;
    if (!(slope > 0.0)) break;  // at a double root: slope 0
    const double step = value / slope;
    lambda -= step;
    if (std::abs(step) <= tolerance) break;
  }

  const Eigen::Vector3d r0(a - lambda, d, e);
  const Eigen::Vector3d r1(d, b - lambda, f);
  const Eigen::Vector3d r2(e, f, c - lambda);
  const Eigen::Vector3d c01 = r0.cross(r1);
  const Eigen::Vector3d c02 = r0.cross(r2);
  const Eigen::Vector3d c12 = r1.cross(r2);
  const double n01 = c01.squaredNorm();
  const double n02 = c02.squaredNorm();
  const double n12 = c12.squaredNorm();
  double best = n01;
  Eigen::Vector3d vector = c01;
  if (n02 > best) {
    best = n02;
    vector = c02;
  }
  if (n12 > best) {
    best = n12;
    vector = c12;
  }
  // The rows span a plane (rank 2) unless the smallest eigenvalue is (nearly) double; the cross
  // product of two rows then has a length of the order of the other eigenvalues' product.
  if (best > 1e-12 * trace * trace * trace * trace) return vector / std::sqrt(best);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov, Eigen::ComputeEigenvectors);
  return solver.eigenvectors().col(0);
}

}  // namespace facet::normals
