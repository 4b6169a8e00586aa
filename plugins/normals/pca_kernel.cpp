#include "normals/pca_kernel.hpp"

#include <algorithm>
#include <limits>

#include "normals/smallest_eigenvector.hpp"

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
  const auto n = static_cast<std::size_t>(width);
  for (auto& sums : column_sums_)
    sums.resize(n);
  for (auto& sums : window_sums_)
    sums.resize(n);
  const float* col_factor = grid.col_factor.data();

  for (int y = 0; y < height; ++y) {
    auto* out = normals.ptr<float>(y);
    std::fill(out, out + 3 * width, kNaN);
    if (y < h || y >= height - h || width <= 2 * h) continue;

    // Column sums of the moments over the window's rows. Branch-free (an invalid point adds
    // zeros), so the loop vectorises.
    for (auto& sums : column_sums_)
      std::fill(sums.begin(), sums.end(), 0.0);
    for (int v = y - h; v <= y + h; ++v) {
      add_row_moments(z.ptr<float>(v), col_factor, grid.row_factor[static_cast<std::size_t>(v)],
                      grid.scale_by_z, width);
    }
    // Window sums: k shifted copies of the column sums, one moment at a time.
    for (int m = 0; m < kMoments; ++m) {
      const double* col = column_sums_[static_cast<std::size_t>(m)].data();
      double* win = window_sums_[static_cast<std::size_t>(m)].data();
      std::fill(win, win + width, 0.0);
      for (int k = -h; k <= h; ++k) {
        for (int x = h; x < width - h; ++x)
          win[x] += col[x + k];
      }
    }

    const float* centre_row = z.ptr<float>(y);
    const double centre_row_factor = grid.row_factor[static_cast<std::size_t>(y)];
    for (int x = h; x < width - h; ++x) {
      const float centre = centre_row[x];
      const auto at = [&](int m) { return window_sums_[static_cast<std::size_t>(m)][x]; };
      if (!(centre == centre) || at(kN) < min_points) continue;
      const double inv_n = 1.0 / at(kN);
      const Eigen::Vector3d mean(at(kX) * inv_n, at(kY) * inv_n, at(kZ) * inv_n);
      Eigen::Matrix3d cov;
      cov(0, 0) = at(kXX) * inv_n - mean.x() * mean.x();
      cov(0, 1) = at(kXY) * inv_n - mean.x() * mean.y();
      cov(0, 2) = at(kXZ) * inv_n - mean.x() * mean.z();
      cov(1, 1) = at(kYY) * inv_n - mean.y() * mean.y();
      cov(1, 2) = at(kYZ) * inv_n - mean.y() * mean.z();
      cov(2, 2) = at(kZZ) * inv_n - mean.z() * mean.z();
      cov(1, 0) = cov(0, 1);
      cov(2, 0) = cov(0, 2);
      cov(2, 1) = cov(1, 2);
      Eigen::Vector3d normal = smallest_eigenvector(cov);
      const double s_centre = grid.scale_by_z ? centre : 1.0;
      const Eigen::Vector3d p(col_factor[x] * s_centre, centre_row_factor * s_centre, centre);
      const double facing = grid.scale_by_z ? normal.dot(p) : normal.z();
      if (facing > 0.0) normal = -normal;
      out[3 * x + 0] = static_cast<float>(normal.x());
      out[3 * x + 1] = static_cast<float>(normal.y());
      out[3 * x + 2] = static_cast<float>(normal.z());
    }
  }
}

void PcaNormals::add_row_moments(const float* z, const float* col_factor, double row_factor,
                                 bool scale_by_z, int width) {
  double* col[kMoments];
  for (int m = 0; m < kMoments; ++m)
    col[m] = column_sums_[static_cast<std::size_t>(m)].data();
  for (int u = 0; u < width; ++u) {
    const float zf = z[u];
    const bool valid = zf == zf;
    const double pz = valid ? zf : 0.0;
    const double s = scale_by_z ? pz : (valid ? 1.0 : 0.0);
    const double px = col_factor[u] * s;
    const double py = row_factor * s;
    col[kN][u] += valid ? 1.0 : 0.0;
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

}  // namespace facet::normals
