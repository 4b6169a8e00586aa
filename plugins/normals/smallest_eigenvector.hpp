#pragma once
// The eigenvector of the smallest eigenvalue of a symmetric positive semi-definite 3x3 matrix,
// the plane normal of a point covariance.

#include <Eigen/Core>

namespace facet::normals {

// cov: symmetric positive semi-definite. Returns a unit vector (sign arbitrary).
//
// The smallest eigenvalue is found by Newton's method on the characteristic polynomial from 0:
// all its roots are real and >= 0, so from the left of the smallest root Newton converges to it
// monotonically, quadratically once close, and for a point set sampled from a surface that root
// is near 0, so a few steps suffice. No trigonometry (the closed form needs acos and cos). The
// eigenvector is then the largest cross product of two rows of cov - lambda I. When the two
// smallest eigenvalues (nearly) coincide that is ill-defined; Eigen's direct solver decides then.
Eigen::Vector3d smallest_eigenvector(const Eigen::Matrix3d& cov);

}  // namespace facet::normals
