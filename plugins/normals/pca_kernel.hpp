#pragma once
// Normals by principal component analysis of a k x k window (the kernel behind normals.pca).

#include <opencv2/core/mat.hpp>
#include <vector>

#include "normals/depth_space.hpp"
#include "normals/window_moments.hpp"

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
// Per row: window sums of the moments (WindowMoments, running sums in double), the covariance
// and its smallest eigenvector in closed form for all pixels at once (a vectorised loop), then a
// robust solver for the few pixels the closed form does not trust (the two smallest eigenvalues
// nearly equal). Keeps its buffers; not thread-safe, one instance per stage.
class PcaNormals {
 public:
  explicit PcaNormals(PcaOptions options);

  // z: CV_32FC1 (NaN = invalid) in the space of `grid`; normals: (re)allocated CV_32FC3.
  void apply(const cv::Mat& z, const PixelGrid& grid, cv::Mat& normals);

 private:
  void solve_untrusted(const float* centre_z, const PixelGrid& grid, int row, float* out) const;

  PcaOptions options_;
  WindowMoments moments_;
  // The current row's closed-form eigenvectors (NaN: not trusted), structure of arrays.
  std::vector<double> direction_x_, direction_y_, direction_z_;
};

}  // namespace facet::normals
