#pragma once
// Flat objects the table took: a book or magazine about 1 cm thick lies within delta of the
// table, and where no normal edge closed around it, its top grew into the table's patch and
// joined the table. Its points stand out only together: smoothed over a window, the table's
// points lie around 0 above the table and the flat object's at its thickness. A region of the
// table raised so, whose border is a step (not the slow rise of a warped or noisy table), is
// given back to the objects as a patch of its own.
//
// The table takes only the object's points within delta of its plane; the rest, its noisier
// upper half, is left as stripes (pieces the plane cut off the table's patch) and edge pixels.
// Those low points (within max_height_m of the table, in a piece of a cut patch that lies all
// that low) are averaged with the table's, so the region stays whole and its mean height is the
// object's, not that of its lower half; the stripes inside a region found join its patch, and so
// do its edge pixels within that height.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/plane.hpp"

namespace facet::planes {

struct FlatObjectRule {
  int window_px = 9;                // side of the smoothing window; 0 = off
  float min_height_m = 0.006F;      // smoothed height above the table of a raised pixel
  float min_step_m = 0.004F;        // border step: inner band's median height - outer ring's
  std::int64_t min_px = 300;        // smaller raised regions stay with the table
  double min_width_px = 12.0;       // narrower raised regions (strips) stay with the table
  float max_height_m = 0.02F;       // low points off the table averaged in; 0 = the table's only
  float low_patch_fraction = 0.9F;  // a patch is low when this share of its points is that low
};

// Reusable buffers of the search (kept from frame to frame by the stage). The search runs on
// cells of 2 x 2 pixels.
struct FlatObjectBuffers {
  cv::Mat height_m;     // CV_32FC1 per cell: height above the table of its sampled pixel, or 0
  cv::Mat table_px;     // CV_32FC1 per cell: 1 where that pixel is a table or low pixel
  cv::Mat cell_patch;   // CV_32SC1 per cell: the patch of a low candidate pixel, -1 = none
  cv::Mat height_sums;  // CV_64FC1: summed-area tables of the two above
  cv::Mat count_sums;
  cv::Mat raised;      // CV_8UC1
  cv::Mat components;  // CV_32SC1
  cv::Mat region;      // CV_8UC1, one region's box at a time
  cv::Mat closed;
  cv::Mat distance;  // CV_32FC1
  cv::Mat inner;
  cv::Mat outer_far;
  cv::Mat outer_near;
  std::vector<std::int64_t> patch_px;   // per patch id: sampled points off the planes
  std::vector<std::int64_t> low_px;     // ... of them within max_height_m of the table
  std::vector<char> low_patch;          // per patch id: a low piece
  std::vector<std::int64_t> inside_px;  // per patch id: its pixels inside a region found
  std::vector<std::int32_t> region_id;  // per patch id: the new patch of that region
};

// plane_labels: CV_32SC1 plane index + 1 per pixel (0 = none); table_label: the table's value
// there; left_labels: CV_32SC1 patch ids left for objects (1..patch_count); xyz: CV_32FC3 points
// (metres, NaN = invalid); all the same size. Each raised region found leaves the table: its
// pixels get plane label 0 and a new patch id (patch_count + 1, ...) in left_labels. Returns the
// new patch count; `moved_px` receives how many pixels left the table (the low pixels that join
// a region were on no plane and are not counted).
std::int32_t give_flat_objects_back(cv::Mat& plane_labels, std::int32_t table_label,
                                    cv::Mat& left_labels, std::int32_t patch_count,
                                    const std::vector<char>& cut_pieces, const cv::Mat& xyz,
                                    const algo::Plane& table, const FlatObjectRule& rule,
                                    FlatObjectBuffers& buffers, std::int64_t& moved_px);

}  // namespace facet::planes
