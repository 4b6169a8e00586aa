#pragma once
// Keeping only blobs that stand on or in front of the support planes: a blob mostly behind a
// table, floor or wall plane is background seen beyond it (the floor past a table's edge, a
// room behind a doorway), not a graspable object.

#include <cstdint>
#include <opencv2/core/mat.hpp>

#include "blobs/euclidean_regions.hpp"
#include "facet/types/geometry.hpp"

namespace facet::blobs {

// Removes (sets to 0) blobs with more than max_behind_fraction of their points further than
// margin_m behind any plane, then renumbers the rest 1..count keeping their order. Returns how
// many were removed.
std::int32_t drop_blobs_behind_planes(EuclideanRegions& blobs, const cv::Mat& xyz,
                                      const SupportPlanes& planes, double max_behind_fraction,
                                      float margin_m);

}  // namespace facet::blobs
