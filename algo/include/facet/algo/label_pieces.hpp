#pragma once
// Splitting labels into their connected pieces: a label that is meant to be one surface but
// holds several (what a support plane leaves of a patch that ran over several objects' tops)
// becomes one label per piece.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/disjoint_sets.hpp"
#include "facet/algo/neighbour_gate.hpp"

namespace facet::algo {

// Keeps its working memory between calls, so one instance serves one thread.
class LabelPieces {
 public:
  // labels: CV_32SC1 ids 0..count (0 = none), continuous, updated in place. split[id] != 0
  // marks the ids to split (ids beyond split.size() are left alone). points: CV_32FC3 in metres,
  // same size, continuous. Two pixels of one id are in one piece when they are 8-neighbours and
  // their points pass `gate`; a pixel without a finite point is a piece of its own. The largest
  // piece of an id keeps it (of equal ones, the first in raster order); the others get the ids
  // count + 1, count + 2, ... in raster order of their first pixel. Returns the new count.
  std::int32_t split(cv::Mat& labels, std::int32_t count, const std::vector<char>& split,
                     const cv::Mat& points, const NeighbourGate& gate);

 private:
  std::vector<std::int32_t> pixels_;   // the pixels to split, in raster order
  std::vector<std::int32_t> compact_;  // per pixel: its index in pixels_ (valid where marked)
  DisjointSets pieces_;                // over the marked pixels, by their index in pixels_
  std::vector<std::int32_t> size_px_;  // per root: its piece's size, then its new id
  std::vector<std::int32_t> largest_;  // per id: the root of its largest piece
};

}  // namespace facet::algo
