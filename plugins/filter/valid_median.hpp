#pragma once
// Median filter over the valid pixels of a depth image (the kernel behind filter.median).

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace facet::filters {

// Computes, for every valid pixel, the median of the valid pixels in its size x size window.
//
// Valid means non-zero for CV_16UC1 millimetres, and finite and positive for CV_32FC1 metres.
// Invalid pixels take no part in any median, and pixels outside the image count as invalid, so
// the border needs no special treatment. With an even number of valid values the lower of the
// two middle values is taken, so every output is a depth that was measured.
//
// An invalid pixel stays invalid (its input value is copied) unless `fill_holes` is set and more
// than half of its window is valid; then it gets the median of those valid pixels.
//
// The object keeps its scratch buffers, so filtering a stream of frames allocates only the
// output images. Not thread-safe: use one instance per thread.
class ValidMedian {
 public:
  // size_px: 3 or 5; throws std::invalid_argument otherwise.
  ValidMedian(int size_px, bool fill_holes);

  // depth: CV_16UC1 or CV_32FC1; throws std::invalid_argument for other types.
  cv::Mat apply(const cv::Mat& depth);

  int size_px() const { return size_px_; }
  bool fill_holes() const { return fill_holes_; }

 private:
  cv::Mat apply_u16(const cv::Mat& depth);
  cv::Mat apply_f32(const cv::Mat& depth);

  int size_px_;
  bool fill_holes_;
  // Each padded buffer remembers the image size it was laid out for: its border and the columns
  // beyond the image are written only then, and must be laid out again for any other size.
  std::vector<std::int16_t> padded_u16_;
  cv::Size padded_u16_for_;
  std::vector<std::int16_t> row_u16_;
  std::vector<float> padded_f32_;
  cv::Size padded_f32_for_;
  std::vector<float> row_f32_;
};

}  // namespace facet::filters
