#pragma once
// Box average of a normal image (optional step of normals.cross).

#include <opencv2/core/mat.hpp>
#include <vector>

namespace facet::normals {

// Averages each valid normal with the valid normals of its (2R+1)^2 window.
//
// Only valid (non-NaN) normals take part, so smoothing never spreads a hole and never gives a
// normal to a pixel that had none. Without renormalisation the result is the mean of unit
// vectors: its length is 1 on a smooth surface and drops where the normals in the window
// disagree, which lowers the dot products of neighbours at creases (the authors' implicit extra
// edge cue). With renormalisation the result is a unit vector again.
//
// Keeps its scratch rows between calls; not thread-safe, one instance per stage.
class NormalSmoother {
 public:
  NormalSmoother(int radius_px, bool renormalize);

  // normals: CV_32FC3; smoothed is (re)allocated to the same size and must not alias it.
  void apply(const cv::Mat& normals, cv::Mat& smoothed);

 private:
  static void window_sum(const float* __restrict padded, int width, int r, float* __restrict out);
  void finish_row(const float* __restrict centre, int width, float* __restrict out) const;

  int radius_px_;
  bool renormalize_;
  // The normals split into planes x, y, z (0 where invalid) and valid (1 or 0).
  std::vector<float> planes_;
  // Column sums over the window's rows, structure of arrays: x, y, z and the valid count.
  std::vector<float> sum_x_, sum_y_, sum_z_, count_;
  // Their sums over the window's columns.
  std::vector<float> win_x_, win_y_, win_z_, win_count_;
};

}  // namespace facet::normals
