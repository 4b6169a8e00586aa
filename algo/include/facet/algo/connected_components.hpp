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

  // Calls visit(id, row, begin, end) for each run [begin, end) of row `row` that belongs to a
  // labelled component of the last label() call, in raster order. Reads the runs, not the image.
  template <typename Visit>
  void for_each_run(Visit&& visit) const {
    for (std::size_t row = 0; row + 1 < row_first_.size(); ++row) {
      for (std::size_t i = row_first_[row]; i < row_first_[row + 1]; ++i) {
        const std::int32_t id = id_of_run(i);
        if (id != 0) visit(id, static_cast<int>(row), runs_[i].begin, runs_[i].end);
      }
    }
  }

  // Renumbers the components of the last label() call: component id becomes new_id[id] (index 0
  // unused; 0 drops it), and the new ids must be 1..n without gaps. The components' pixels in
  // `labels` (what label() wrote) are rewritten run by run; size_px() then answers for the new
  // ids. Throws std::invalid_argument when new_id has not count + 1 entries or is not 1..n.
  void relabel(const std::vector<std::int32_t>& new_id, cv::Mat& labels);

 private:
  struct Run {
    int begin;  // first column
    int end;    // one past the last column
  };

  void find_runs(const cv::Mat& image, std::uint8_t value);
  void join_touching_runs(int connectivity);
  void write_labels(cv::Mat& labels) const;
  std::int32_t id_of_run(std::size_t run) const {
    return id_[static_cast<std::size_t>(runs_joined_.parent(static_cast<std::int32_t>(run)))];
  }

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
