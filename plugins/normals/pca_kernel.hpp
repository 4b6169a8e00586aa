#pragma once
// Normals by principal component analysis of a k x k window (the kernel behind normals.pca).

#include <array>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "normals/depth_space.hpp"

namespace facet::normals {

struct PcaOptions {
  int window_px = 5;         // odd, >= 3
  int min_valid_points = 3;  // valid points the window needs (at least 3)
};

// For every pixel whose depth is valid and whose k x k window lies inside the image and holds at
// least `min_valid_points` valid points: the eigenvector of the smallest eigenvalue of those
// points' covariance, as a unit normal oriented towards the camera (metric: n . p < 0; image:
// negative third component). NaN elsewhere. Invalid points are left out of the window, never
// replaced by a value.
//
// Window sums are built separably (column sums over k rows, then k columns) in double
// precision, so the covariance E[pp^T] - E[p]E[p]^T does not lose the small variance of a plane
// to cancellation. Keeps its scratch rows; not thread-safe, one instance per stage.
class PcaNormals {
 public:
  explicit PcaNormals(PcaOptions options);

  // z: CV_32FC1 (NaN = invalid) in the space of `grid`; normals: (re)allocated CV_32FC3.
  void apply(const cv::Mat& z, const PixelGrid& grid, cv::Mat& normals);

 private:
  // n, x, y, z, xx, xy, xz, yy, yz, zz
  static constexpr int kMoments = 10;
  PcaOptions options_;
  void add_row_moments(const float* z, const float* col_factor, double row_factor, bool scale_by_z,
                       int width);

  std::array<std::vector<double>, kMoments> column_sums_;  // over the window's rows
  std::array<std::vector<double>, kMoments> window_sums_;  // over the whole window
};

}  // namespace facet::normals
