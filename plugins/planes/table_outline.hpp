#pragma once
// The table's visible extent, for the scene model's test "objects stand inside the table"
// (grow.blobs): the convex hull of the table's points, seen along world up.
//
// Convex, because objects hide parts of the table: the hull covers the table under and behind
// them, which a traced outline of the visible pixels would not.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/plane.hpp"

namespace facet::planes {

// Points of the pixels whose plane label is in `table_ids` (plane ids, 1-based flags) and whose
// patch is a table patch (`table_patches`, flags indexed by patch label), on every
// `stride_px`-th row and column, projected onto `table`, then their convex hull: vertices on the
// table plane (camera frame, metres), counter-clockwise seen from above (along -up). Empty when
// fewer than three points span an area.
//
// Only table patches count, although other pixels within delta of the table's plane are the
// table's in the plane labels: the plane is infinite. A far wall breaks into stripes at its
// disparity steps, and the row where it crosses the table's height lies on the table's plane as
// wide as the room; with that row in the hull, the table reached the wall, and every stripe of
// the wall stood inside it.
std::vector<Eigen::Vector3d> table_outline(const cv::Mat& plane_labels, const cv::Mat& patch_labels,
                                           const std::vector<char>& table_patches,
                                           const cv::Mat& xyz, const std::vector<char>& table_ids,
                                           const algo::Plane& table, const Eigen::Vector3f& up,
                                           int stride_px);

}  // namespace facet::planes
