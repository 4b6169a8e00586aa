#pragma once
// Closed-form eigenvector of the smallest eigenvalue of a symmetric 3x3 matrix, branch-free so
// that a loop over pixels vectorises.

#include <algorithm>
#include <cmath>

namespace facet::normals {

// The upper triangle of a symmetric 3x3 matrix.
struct SymmetricMatrix3 {
  double xx, xy, xz, yy, yz, zz;
};

struct Direction3 {
  double x, y, z;
};

// t(w) = cos(2 pi / 3 + (2 / 3) asin(w)) for w in [0, 1], the smallest root of the Chebyshev
// cubic 4 t^3 - 3 t = r with w = sqrt((1 - r) / 2). t is analytic on the closed interval (also at
// w = 1, where it behaves like -cos of an even argument), so a polynomial converges fast: these
// are the monomial coefficients of the degree-10 Chebyshev interpolant of t on [0, 1] (11
// Chebyshev nodes), max error 8.2e-11. The leading terms are close to the Taylor series at 0,
// -1/2 - w / sqrt(3) + w^2 / 9 ...
//
// Evaluated by Estrin's scheme (pairs, then pairs of pairs with w^2, w^4, w^8): 5 dependent
// steps instead of Horner's 20, which matters in a loop that is bound by its latency chain.
inline double smallest_chebyshev_root(double w) {
  constexpr double c[] = {-0.50000000008108136,   -0.57735024949994906,   0.11111030974855743,
                          -0.053445442848274377,  0.032813031205975562,   -0.022319909201495524,
                          0.015279987592211084,   -0.0093781300344992578, 0.0044852940675561758,
                          -0.0014024871832754634, 0.00020759627858007497};
  const double w2 = w * w;
  const double w4 = w2 * w2;
  const double w8 = w4 * w4;
  const double low = (c[0] + c[1] * w) + (c[2] + c[3] * w) * w2;
  const double mid = (c[4] + c[5] * w) + (c[6] + c[7] * w) * w2;
  const double high = (c[8] + c[9] * w) + c[10] * w2;
  return (low + mid * w4) + high * w8;
}

// Writes an eigenvector of the smallest eigenvalue of `m` to `direction`: sign arbitrary, not
// normalised (its squared length is about ((lambda_1 - lambda_0)(lambda_2 - lambda_0))^2 /
// trace^4, at least 1e-10 when trusted), so that the caller can normalise it in single precision
// after converting. Returns false when it is not reliable: the two smallest eigenvalues (nearly)
// coincide, or `m` is zero or not finite; the caller then needs a robust solver. Precision
// argument:
//
// 1. The matrix is divided by its trace, so everything below is of order 1 whatever the unit.
// 2. Trigonometric solution of the characteristic cubic (all roots real for a symmetric
//    matrix): with q = trace / 3 (= 1/3 after scaling), B = (M - q I) / p and
//    p^2 = |M - q I|_F^2 / 6, the eigenvalues are q + 2 p cos(acos(r) / 3 + 2 pi k / 3) with
//    r = det(B) / 2 in [-1, 1]; k = 1 gives the smallest. The cosine of the angle is the
//    polynomial above in w = sqrt((1 - r) / 2), so no acos and cos are needed.
// 3. The eigenvector is the longest cross product of two rows of M - lambda I: each such product
//    is a row of adj(M - lambda I) = sum_j prod_{k != j} (lambda_k - lambda) v_j v_j^T, which for
//    lambda = lambda_0 is (lambda_1 - lambda_0)(lambda_2 - lambda_0) v_0 v_0^T. An error d in
//    lambda tilts the result by about d / (lambda_1 - lambda_0). The cubic route loses accuracy
//    in r when lambda_0 and lambda_1 are close (d grows like eps / (lambda_1 - lambda_0)), so
//    the result is trusted only when the squared length of that cross product, about
//    ((lambda_1 - lambda_0)(lambda_2 - lambda_0))^2, exceeds 1e-10 (trace 1): the tilt then
//    stays below about 1e-5 in double precision.
inline bool closed_form_smallest_eigenvector(const SymmetricMatrix3& m, Direction3& direction) {
  const double inv_trace = 1.0 / (m.xx + m.yy + m.zz);
  const double a = m.xx * inv_trace;
  const double b = m.yy * inv_trace;
  const double c = m.zz * inv_trace;
  const double d = m.xy * inv_trace;
  const double e = m.xz * inv_trace;
  const double f = m.yz * inv_trace;
  constexpr double kThird = 1.0 / 3.0;
  const double ba = a - kThird;
  const double bb = b - kThird;
  const double bc = c - kThird;
  const double p_sq = (ba * ba + bb * bb + bc * bc + 2.0 * (d * d + e * e + f * f)) * (1.0 / 6.0);
  const double p = std::sqrt(p_sq);
  const double det = ba * (bb * bc - f * f) - d * (d * bc - f * e) + e * (d * f - bb * e);
  // NaN (p = 0: all eigenvalues equal) passes through and fails the final test.
  const double r = std::min(std::max(det / (2.0 * p_sq * p), -1.0), 1.0);
  const double lambda = kThird + 2.0 * p * smallest_chebyshev_root(std::sqrt(0.5 - 0.5 * r));

  const double a0 = a - lambda;
  const double b1 = b - lambda;
  const double c2 = c - lambda;
  // Rows (a0, d, e), (d, b1, f), (e, f, c2) and their pairwise cross products.
  const double x01 = d * f - e * b1, y01 = e * d - a0 * f, z01 = a0 * b1 - d * d;
  const double x02 = d * c2 - e * f, y02 = e * e - a0 * c2, z02 = a0 * f - d * e;
  const double x12 = b1 * c2 - f * f, y12 = f * e - d * c2, z12 = d * f - b1 * e;
  const double n01 = x01 * x01 + y01 * y01 + z01 * z01;
  const double n02 = x02 * x02 + y02 * y02 + z02 * z02;
  const double n12 = x12 * x12 + y12 * y12 + z12 * z12;
  const bool use02 = n02 > n01;
  double best = use02 ? n02 : n01;
  double x = use02 ? x02 : x01;
  double y = use02 ? y02 : y01;
  double z = use02 ? z02 : z01;
  const bool use12 = n12 > best;
  best = use12 ? n12 : best;
  x = use12 ? x12 : x;
  y = use12 ? y12 : y;
  z = use12 ? z12 : z;
  direction = {x, y, z};
  return best > 1e-10;
}

}  // namespace facet::normals
