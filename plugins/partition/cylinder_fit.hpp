#pragma once
// One circular cylinder through two curved patches: the pieces of a can lying on the table that
// an occluder in front cuts in two. The general quadric of the curvature feature cannot tell
// such pieces apart from two planes facing the camera: seen from above, each piece spans only a
// few centimetres of depth, and the algebraic fit settles on the pair of planes z = d1, z = d2.
// A cylinder is fitted geometrically instead: its axis is the direction every surface normal is
// perpendicular to, its cross-section a circle through the points projected along that axis.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "partition/blob_segments.hpp"

namespace facet::partition {

// Points of a patch with their 3D normals.
struct OrientedSamples {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;
};

struct CylinderRule {
  double tolerance_m = 0.005;  // a point this close to the cylinder's surface fits it
  double min_share = 0.8;      // least share of each patch's points that fit
  double max_radius_m = 0.15;  // wider: a gently bent surface, not a table-top cylinder
};

// Up to `max_samples` points of `segment`, spread over it, each with the normal of the cross
// product of its neighbours `step_px` away along the row and the column in `point_image`
// (CV_32FC3, continuous). A point whose four neighbours do not all have a point, or lie across
// a depth step, is left out.
void take_oriented_samples(const BlobSegments& points, const Segment& segment,
                           const cv::Mat& point_image, std::int32_t max_samples,
                           OrientedSamples& out);

// True when one circular cylinder of radius at most rule.max_radius_m fits both: its axis is
// perpendicular to the normals of both patches (each patch weighted equally), the normals turn
// about it by more than noise does on a plane, and at least rule.min_share of each patch's points
// lie within rule.tolerance_m of it.
bool one_circular_cylinder(const OrientedSamples& a, const OrientedSamples& b,
                           const CylinderRule& rule);

}  // namespace facet::partition
