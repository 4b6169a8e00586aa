#pragma once
// The eigenvector of the smallest eigenvalue of a symmetric positive semi-definite 3x3 matrix,
// the robust (slow) path for the matrices the closed form does not trust.

#include <Eigen/Core>

namespace facet::normals {

// cov: symmetric positive semi-definite. Returns a unit vector (sign arbitrary); the z axis when
// cov is zero (all points equal: no direction). Eigen's iterative solver (Householder
// tridiagonalisation and QL), accurate also when the two smallest eigenvalues (nearly) coincide,
// where the closed form loses precision; the eigenvector is then any vector of their eigenspace.
Eigen::Vector3d smallest_eigenvector(const Eigen::Matrix3d& cov);

}  // namespace facet::normals
