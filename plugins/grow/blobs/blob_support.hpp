#pragma once
// Keeping only blobs that stand on or in front of the support planes: a blob mostly behind a
// table, floor or wall plane is background seen beyond it (the floor past a table's edge, a
// room behind a doorway), and a blob lying mostly within a plane's band is a shred of that
// plane (a strip of table between an object's silhouette and an edge), not a graspable object.
// With a table (planes.support's scene model), a blob must also stand on it: rise above the table
// plane (the table's front edge, its underside and whatever is below it do not) and stand inside
// the table's outline (a chair or a wall's shreds seen beyond the table do not).

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "blobs/euclidean_regions.hpp"
#include "facet/types/geometry.hpp"

namespace facet::blobs {

struct BackgroundBlobRule {
  bool drop_behind = true;           // apply the behind test
  double max_behind_fraction = 0.5;  // share of points further than behind_margin_m behind
  float behind_margin_m = 0.03F;
  double max_on_plane_fraction = 0.5;  // share of points within on_plane_distance_m; > 1 = off
  float on_plane_distance_m = 0.012F;
  // The table tests; off when the planes name no table.
  bool on_table = true;
  float min_rise_m = 0.006F;          // a point this high above the table rises above it
  double min_raised_fraction = 0.5;   // share of a blob's points that must rise
  float table_margin_m = 0.03F;       // the outline grown by this much
  double max_outside_fraction = 0.5;  // share of a blob's footprint outside the outline
};

struct DroppedBlobs {
  std::int32_t behind = 0;         // blobs mostly behind a plane
  std::int32_t on_plane = 0;       // blobs mostly within a plane's band
  std::int32_t not_raised = 0;     // blobs that do not rise above the table
  std::int32_t outside_table = 0;  // blobs standing beyond the table's outline
};

// Keeps the blobs with keep[id] != 0 (keep has count + 1 entries), sets the others to 0 and
// renumbers the kept ones 1..count in their order. Returns how many were removed.
std::int32_t keep_blobs(EuclideanRegions& blobs, const std::vector<char>& keep);

// Removes (sets to 0) the blobs that one of the rule's tests finds to be background, then
// renumbers the rest 1..count keeping their order.
DroppedBlobs drop_background_blobs(EuclideanRegions& blobs, const cv::Mat& xyz,
                                   const SupportPlanes& planes, const BackgroundBlobRule& rule);

}  // namespace facet::blobs
