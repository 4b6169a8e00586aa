#pragma once
// How much of a normal image's disagreement is noise (normals.cross's automatic smoothing).
//
// The edge filter marks a pixel when its normal and a neighbour's a few pixels away differ by
// more than its angle. On a sensor noisier than the one the defaults were chosen on, that happens
// all over flat surfaces: patches shrink to nothing and the table is not found. The measure is
// the share of pixel pairs, `step_px` apart along the rows and along the columns, whose normals
// differ by more than the edge filter's angle (|cosine| below `edge_threshold`), taken of the
// normals as they are or box-averaged over a radius (NormalSmoother). Creases and noise both make
// such pairs; averaging removes those of noise and keeps those of creases, so what one more radius
// of averaging removes tells how noisy the normals are, however many creases the scene has.

#include <opencv2/core/mat.hpp>

namespace facet::normals {

struct NoisyPairRule {
  int step_px = 3;               // the distance of the pair: the edge filter's reach
  double edge_threshold = 0.85;  // the edge filter's: a pair disagrees below this |cosine|
  int stride_px = 4;             // every n-th row and column is looked at: 1/16 of the pixels
};

// normals: CV_32FC3 (NaN = none; normals shorter than 1, as smoothing without renormalisation
// leaves them, are fine). Pairs with a missing normal do not count. Returns 0 for an image
// without a valid pair. The normals averaged over a radius are NormalSmoother's to make.
double noisy_pair_share(const cv::Mat& normals, const NoisyPairRule& rule);

}  // namespace facet::normals
