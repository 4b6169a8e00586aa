#pragma once
// The last kernel of planes.support: which pixels join the accepted support planes, and what is
// left of each surface patch for the objects.
//
// Largest plane first, a valid point within delta of a support plane joins the first such plane
// (what taking the planes one after the other would give), also out of its patch, unless its
// patch is an object face:
//   - a patch that lies mostly well off the planes (at least object_face_off_plane_fraction of
//     its points beyond 2 delta from all): the bottom band of a box side, within delta of the
//     table it stands on, stays with the box;
//   - for the horizontal support planes (table, floor), also a patch whose points within delta
//     of the table lie on average more than half of min_object_height_m above it: the top of a
//     book 1 cm thick, the bottom band of a flat object's side (spread over 0..delta). The
//     table's own points lie around 0.
// The statistics come from one pass over the points: the patches are judged and the planes'
// inliers and RMS made without a second look.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/plane.hpp"
#include "facet/types/geometry.hpp"

namespace facet::planes {

struct AssignmentRule {
  float inlier_distance_m = 0.010F;             // delta
  double object_face_off_plane_fraction = 0.5;  // share of a face's points off every plane
  float min_object_height_m = 0.006F;           // a patch raised this much is an object top
};

struct PlaneAssignment {
  std::int64_t valid_px = 0;  // points of the frame
  std::int64_t plane_px = 0;  // of which joined a plane
  // Per plane (in the order given): its points and their RMS distance from it.
  std::vector<std::int64_t> inliers;
  std::vector<double> rms_m;
  // Per patch slot (0 = no patch, 1..count): its valid points, and per (slot, plane) those
  // within delta of that plane and of no earlier one (joined or not): near_px[slot * planes + c].
  std::vector<std::int64_t> patch_px;
  std::vector<std::int64_t> near_px;
  // Per patch slot: the pixels it keeps.
  std::vector<std::int64_t> left_px;
};

// patch_labels: CV_32SC1 ids 1..patch_count (others count as no patch); xyz: CV_32FC3 points
// (metres, NaN = invalid); both continuous, same size. `roles` per plane; `table` the index of the
// table among `planes` or -1. Writes `plane_labels` (plane index + 1 per pixel, 0 = none) and
// `left_labels` (the patch id a pixel keeps, 0 = joined a plane or no patch), both created as
// CV_32SC1 of the labels' size.
PlaneAssignment assign_to_planes(const cv::Mat& patch_labels, std::int32_t patch_count,
                                 const cv::Mat& xyz, const std::vector<algo::Plane>& planes,
                                 const std::vector<PlaneRole>& roles, int table,
                                 const AssignmentRule& rule, cv::Mat& plane_labels,
                                 cv::Mat& left_labels);

}  // namespace facet::planes
