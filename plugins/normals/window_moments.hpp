#pragma once
// Sums of the ten point moments over the k x k windows of one image row, moved down the image
// one row at a time.

#include <array>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "normals/depth_space.hpp"

namespace facet::normals {

// The moments of a window's valid points p = (x, y, z): their count and the sums of x, y, z and
// of the six products xx, xy, xz, yy, yz, zz.
enum Moment { kCount, kX, kY, kZ, kXX, kXY, kXZ, kYY, kYZ, kZZ, kMomentCount };

// Column sums over the window's k rows are kept as running sums: moving down one row adds the
// entering row's moments and subtracts the leaving row's, O(1) per pixel whatever k. The window
// sums then add k column sums. A point is valid when its z is finite; invalid points add zeros.
//
// Double precision, because the covariance is later taken as E[pp^T] - E[p]E[p]^T from raw
// moments: in disparity units z^2 is about 4e6 while a plane's variance across its normal can be
// 1e-2, a ratio float (eps 6e-8) could not resolve. Double keeps about 1e-9 of it here, and the
// running sums' rounding (at most one ulp of the sum per row, 480 rows) stays far below that.
//
// Keeps its buffers between images; not thread-safe.
class WindowMoments {
 public:
  // Column sums over rows [0, k) of `z`; `z` and `grid` must stay unchanged while sliding.
  void start(const cv::Mat& z, const PixelGrid& grid, int window_px);
  // Moves the window rows down by one (the window's top row was `first_row` - 1).
  void slide_to(int first_row);
  // Window sums, valid for x in [k/2, width - k/2), of the current rows.
  void sum_windows();
  const double* window_sum(Moment m) const {
    return window_sums_[static_cast<std::size_t>(m)].data();
  }

 private:
  void update_columns(int entering_row, int leaving_row);

  const cv::Mat* z_ = nullptr;
  const PixelGrid* grid_ = nullptr;
  int window_px_ = 0;
  std::array<std::vector<double>, kMomentCount> column_sums_;
  std::array<std::vector<double>, kMomentCount> window_sums_;
};

}  // namespace facet::normals
