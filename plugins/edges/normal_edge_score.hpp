#pragma once
// The 8-direction surface-normal edge score (paper eq. 3 and 4) on a whole image.
//
// For each direction d of the 8 neighbours, s_d = mean over k = 1..R of |n(p) · n(p + k·d)|.
// The score is min_d s_d ('max' variant: the strongest angle change wins) or mean_d s_d ('avg').
// Pixels whose normal or any of the 8·R neighbours' normals is NaN, and pixels within R of the
// image border, get score 0.

#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/parallel.hpp"

namespace facet::edges {

enum class DirectionCombine {
  min,   // the paper's 'max' variant: the largest angle over the 8 directions decides
  mean,  // the 'avg' variant: smoother edge images
};

// What a direction that meets a pixel without a normal (a hole in the depth) counts for.
enum class InvalidNeighbours {
  // The direction is left out of the min or mean; a pixel with no valid direction scores 0. A
  // hole is unassigned itself but is no evidence of a crease beside it: next to a one-pixel
  // dropout line, the pixels keep the score their valid neighbours give them.
  skip,
  // Any invalid neighbour makes the pixel's score 0: a hole grows into an edge band R pixels
  // wider on each side (plus the normal stage's own radius), which swallows small, far objects.
  edge,
};

// The working memory of one band of rows being scored.
struct EdgeWorkspace {
  std::vector<float> dots;  // |dot products| of R+1 rows, see the .cpp for the layout
  std::vector<float> sums;  // one row of per-direction sums for each of the 8 directions
};

class NormalEdgeScorer {
 public:
  // reach_px: R, the number of pixels averaged along each direction (1 or 3).
  NormalEdgeScorer(int reach_px, DirectionCombine combine,
                   InvalidNeighbours invalid = InvalidNeighbours::edge);

  // normals: CV_32FC3 (NaN = no normal). Returns the score, CV_32FC1 of the same size. Bands of
  // rows are scored on `runner`'s threads when one is given; the result does not depend on it.
  // Not const: the scorer keeps its working memory between calls to avoid reallocations.
  cv::Mat score(const cv::Mat& normals, ParallelRunner* runner = nullptr);

  int reach_px() const { return reach_px_; }

 private:
  int reach_px_;
  DirectionCombine combine_;
  InvalidNeighbours invalid_;
  std::vector<float> planes_;  // normals as three planes (x, y, z), one float per pixel each
  WorkspacePool<EdgeWorkspace> workspaces_;
};

// 255 where score <= threshold (edge), 0 where score > threshold (surface). CV_8UC1.
cv::Mat edge_mask(const cv::Mat& score, float threshold);

}  // namespace facet::edges
