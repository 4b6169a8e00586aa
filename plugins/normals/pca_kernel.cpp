#include "normals/pca_kernel.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>

namespace facet::normals {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

enum Moment { kN, kX, kY, kZ, kXX, kXY, kXZ, kYY, kYZ, kZZ };

}  // namespace

PcaNormals::PcaNormals(PcaOptions options) : options_(options) {}

void PcaNormals::apply(const cv::Mat& z, const PixelGrid& grid, cv::Mat& normals) {
  CV_Assert(z.type() == CV_32FC1);
  const int width = z.cols;
  const int height = z.rows;
  const int h = options_.window_px / 2;
  const int min_points = std::max(3, options_.min_valid_points);
  normals.create(height, width, CV_32FC3);
  normals.setTo(cv::Scalar::all(kNaN));
  for (auto& sums : column_sums_)
    sums.resize(static_cast<std::size_t>(width));
  std::array<double*, kMoments> col{};
  for (int m = 0; m < kMoments; ++m)
    col[static_cast<std::size_t>(m)] = column_sums_[m].data();
  const float* col_factor = grid.col_factor.data();

  for (int y = h; y < height - h; ++y) {
    for (auto& sums : column_sums_)
      std::fill(sums.begin(), sums.end(), 0.0);
    for (int v = y - h; v <= y + h; ++v) {
      const float* zrow = z.ptr<float>(v);
      const double row_factor = grid.row_factor[static_cast<std::size_t>(v)];
      for (int u = 0; u < width; ++u) {
        const float zf = zrow[u];
        if (!(zf == zf)) continue;
        const double pz = zf;
        const double s = grid.scale_by_z ? pz : 1.0;
        const double px = col_factor[u] * s;
        const double py = row_factor * s;
        col[kN][u] += 1.0;
        col[kX][u] += px;
        col[kY][u] += py;
        col[kZ][u] += pz;
        col[kXX][u] += px * px;
        col[kXY][u] += px * py;
        col[kXZ][u] += px * pz;
        col[kYY][u] += py * py;
        col[kYZ][u] += py * pz;
        col[kZZ][u] += pz * pz;
      }
    }

    const float* centre_row = z.ptr<float>(y);
    const double centre_row_factor = grid.row_factor[static_cast<std::size_t>(y)];
    auto* out = normals.ptr<float>(y);
    for (int x = h; x < width - h; ++x) {
      const float centre = centre_row[x];
      if (!(centre == centre)) continue;
      std::array<double, kMoments> s{};
      for (int u = x - h; u <= x + h; ++u) {
        for (int m = 0; m < kMoments; ++m)
          s[static_cast<std::size_t>(m)] += col[m][u];
      }
      if (s[kN] < min_points) continue;
      const double inv_n = 1.0 / s[kN];
      const Eigen::Vector3d mean(s[kX] * inv_n, s[kY] * inv_n, s[kZ] * inv_n);
      Eigen::Matrix3d cov;
      cov(0, 0) = s[kXX] * inv_n - mean.x() * mean.x();
      cov(0, 1) = s[kXY] * inv_n - mean.x() * mean.y();
      cov(0, 2) = s[kXZ] * inv_n - mean.x() * mean.z();
      cov(1, 1) = s[kYY] * inv_n - mean.y() * mean.y();
      cov(1, 2) = s[kYZ] * inv_n - mean.y() * mean.z();
      cov(2, 2) = s[kZZ] * inv_n - mean.z() * mean.z();
      cov(1, 0) = cov(0, 1);
      cov(2, 0) = cov(0, 2);
      cov(2, 1) = cov(1, 2);
      // Closed-form 3x3 solver (Cardano, trigonometric form); eigenvalues come out ascending.
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
      solver.computeDirect(cov, Eigen::ComputeEigenvectors);
      Eigen::Vector3d normal = solver.eigenvectors().col(0);
      const double s_centre = grid.scale_by_z ? centre : 1.0;
      const Eigen::Vector3d p(col_factor[x] * s_centre, centre_row_factor * s_centre, centre);
      const double facing = grid.scale_by_z ? normal.dot(p) : normal.z();
      if (facing > 0.0) normal = -normal;
      normal.normalize();
      out[3 * x + 0] = static_cast<float>(normal.x());
      out[3 * x + 1] = static_cast<float>(normal.y());
      out[3 * x + 2] = static_cast<float>(normal.z());
    }
  }
}

}  // namespace facet::normals
