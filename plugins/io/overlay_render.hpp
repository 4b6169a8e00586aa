#pragma once
// The overlay picture io.overlay writes and io.view shows: depth as grey, segments blended in
// stable colours, their borders, and optionally the normal edges. Part of facet_io_support, the
// io code other plugins share.

#include <opencv2/core/mat.hpp>

#include "facet/parallel.hpp"
#include "io/label_palette.hpp"

namespace facet::io {

struct OverlayStyle {
  double near_m = 0.0;  // depth drawn brightest; near_m = far_m = 0: per-frame auto range
  double far_m = 0.0;   // depth drawn darkest (but still brighter than invalid)
  double alpha = 0.5;   // weight of the segment colour over the grey, 0..1
  bool draw_borders = true;
  Rgb border_colour{0, 0, 0};
  bool draw_edges = true;
  Rgb edge_colour{255, 0, 255};
};

// The depth range [near, far] in metres that maps to grey.
struct GreyRange {
  double near_m = 0.0;
  double far_m = 0.0;
};

// The 1st and 99th percentile of the valid depths (at millimetre resolution), so a few stray
// pixels do not squeeze the grey range; {0, 0} when no pixel is valid.
GreyRange auto_grey_range(const cv::Mat& depth);

// Renders the overlay as CV_8UC3 (BGR). `depth` is CV_16UC1 mm or CV_32FC1 m; `labels` (CV_32SC1,
// or empty for none) and `edge_mask` (CV_8UC1, 255 = edge, or empty for none) are of its size.
// Bands of rows are drawn on `runner`'s threads when one is given.
cv::Mat render_overlay(const cv::Mat& depth, const cv::Mat& labels, const cv::Mat& edge_mask,
                       const OverlayStyle& style, ParallelRunner* runner = nullptr);

}  // namespace facet::io
