#pragma once
// Labelled connected components of the pixels of one value in an 8-bit image, found through runs
// of pixels rather than pixel by pixel: a region of a depth image is a few hundred runs, not tens
// of thousands of pixels. grow.surfaces labels its surface pixels with it, partition.graph the
// regions no patch claimed.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/disjoint_sets.hpp"

namespace facet::algo {

struct Components {
  std::int32_t count = 0;        // labels 1..count
  std::int64_t labelled_px = 0;  // pixels carrying a label
};

// Keeps its working memory (runs and their sets) between calls, so one instance serves one
// thread.
class ComponentLabeler {
 public:
  // image: CV_8UC1; its pixels equal to `value` are labelled. connectivity: 4 or 8. labels:
  // CV_32SC1 of the image's size (the caller's, possibly a view into a larger buffer), written
  // whole: 1..count, ids in raster order (row, then column) of each component's first pixel, 0
  // for other pixels and for components smaller than min_size_px. The result depends on nothing
  // but the input. Throws std::invalid_argument for other types, sizes or connectivities.
  Components label(const cv::Mat& image, std::uint8_t value, int connectivity,
                   std::int64_t min_size_px, cv::Mat& labels);

  // Pixels of component `id` (1..count) of the last label() call.
  std::int64_t size_px(std::int32_t id) const { return size_of_id_[static_cast<std::size_t>(id)]; }

 private:
  struct Run {
    int begin;  // first column
    int end;    // one past the last column
  };

  void find_runs(const cv::Mat& image, std::uint8_t value);
  void join_touching_runs(int connectivity);
  void write_labels(cv::Mat& labels) const;

  std::vector<Run> runs_;               // in raster order
  std::vector<std::size_t> row_first_;  // index of each row's first run; one past the end last
  std::vector<std::uint64_t> bits_;     // the pixels of one row equal to the value, one bit each
  // Sets of runs. The root of a set is always its smallest index, i.e. the set's first run in
  // raster order, which gives raster-ordered ids for free.
  DisjointSets runs_joined_;
  std::vector<std::int64_t> size_px_;     // of the set a root run heads
  std::vector<std::int32_t> id_;          // id of a root run, 0 = too small
  std::vector<std::int64_t> size_of_id_;  // per id, 0 unused
};

}  // namespace facet::algo
