#include "normals/smallest_eigenvector.hpp"

#include <Eigen/Eigenvalues>

namespace facet::normals {

Eigen::Vector3d smallest_eigenvector(const Eigen::Matrix3d& cov) {
  if (!(cov.trace() > 0.0)) return Eigen::Vector3d::UnitZ();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov, Eigen::ComputeEigenvectors);
  return solver.eigenvectors().col(0);
}

}  // namespace facet::normals
