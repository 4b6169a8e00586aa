#pragma once
// Connected regions of surface pixels, labelled through runs of pixels rather than pixel by
// pixel: a region of a depth image is a few hundred runs, not tens of thousands of pixels.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/disjoint_sets.hpp"

namespace facet::grow {

// The label image of SurfaceRegions may be read (not written) up to this many pixels before its
// first and after its last pixel; those read 0.
constexpr int kLabelGuardPx = 16;

struct SurfaceRegions {
  // CV_32SC1: 1..count, 0 = not surface or in a region below the minimum size. Continuous, with
  // kLabelGuardPx readable guard pixels on either side.
  cv::Mat labels;
  std::int32_t count = 0;
  std::int64_t labelled_px = 0;  // pixels carrying a label
};

// Keeps its working memory (runs and their union-find) between frames, so one instance serves
// one thread.
class SurfaceRegionLabeler {
 public:
  // classes: CV_8UC1 PixelClass; kSurfacePixel pixels are grown. connectivity: 4 or 8. Regions
  // smaller than min_size_px are left at 0. Ids follow the raster order (row, then column) of
  // each region's first pixel, so the result does not depend on anything but the input.
  SurfaceRegions label(const cv::Mat& classes, int connectivity, std::int64_t min_size_px);

 private:
  struct Run {
    int begin;  // first column
    int end;    // one past the last column
  };

  void find_runs(const cv::Mat& classes);
  void join_touching_runs(int connectivity);
  void write_labels(cv::Mat& labels) const;

  std::vector<Run> runs_;               // in raster order
  std::vector<std::size_t> row_first_;  // index of each row's first run; one past the end last
  std::vector<std::uint64_t> bits_;     // surface pixels of one row, one bit each
  // Sets of runs. The root of a set is always its smallest index, i.e. the set's first run in
  // raster order, which gives raster-ordered region ids for free.
  algo::DisjointSets runs_joined_;
  std::vector<std::int64_t> size_px_;  // of the set a root run heads
  std::vector<std::int32_t> id_;       // region id of a root run, 0 = too small
};

}  // namespace facet::grow
