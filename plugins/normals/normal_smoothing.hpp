#pragma once
// Box average of a normal image (optional step of normals.cross).

#include <functional>
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
// Works row by row on a ring of the 2R+1 input rows the window needs, split into planes
// (x, y, z, valid), so everything it touches stays in the first-level cache: per output row the
// planes are summed over the window's rows, then over its columns. Sums are taken afresh for
// every window (2R+1 terms), not as running sums, so no rounding accumulates across the image.
// Keeps its buffers between calls; not thread-safe, one instance per stage.
class NormalSmoother {
 public:
  NormalSmoother(int radius_px, bool renormalize);

  // Writes row y of the normals to compute (3 * width floats: x, y, z per pixel, NaN = none).
  using RowSource = std::function<void(int y, float* row)>;

  // The normals come row by row from `source`, each row once, in order; smoothed is
  // (re)allocated to height x width CV_32FC3.
  void apply(int height, int width, const RowSource& source, cv::Mat& smoothed);
  // normals: CV_32FC3; smoothed must not alias it.
  void apply(const cv::Mat& normals, cv::Mat& smoothed);

 private:
  static constexpr int kPlanes = 4;  // x, y, z, valid
  float* ring_plane(int image_row, int plane);

  int radius_px_;
  bool renormalize_;
  int width_ = 0;
  std::vector<float> incoming_;  // the row the source writes, interleaved
  // 2R+1 rows of planes, image row v in slot v mod (2R+1).
  std::vector<float> ring_;
  // Per plane: sums over the window's rows, padded with R zeros at both ends so that the sum over
  // the window's columns has the same bounds at every x; then the sums over the columns.
  std::vector<float> column_sums_;
  std::vector<float> window_sums_;
};

}  // namespace facet::normals
