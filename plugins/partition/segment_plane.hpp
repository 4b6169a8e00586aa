#pragma once
// Least-squares planes and bounding boxes of point ranges in the gathered arrays.

#include <array>
#include <cstdint>

#include "facet/algo/plane.hpp"
#include "partition/blob_segments.hpp"

namespace facet::partition {

// A segment's least-squares plane (algo::Plane: unit normal towards the camera, so a positive
// signed distance is in front of the surface), with the centroid of the points it was fitted to.
struct FittedPlane : algo::Plane {
  Eigen::Vector3f centroid_m = Eigen::Vector3f::Zero();
  // In the plane, the directions of the points' largest and second largest spread.
  Eigen::Vector3f axis_u = Eigen::Vector3f::UnitX();
  Eigen::Vector3f axis_v = Eigen::Vector3f::UnitY();
  bool valid = false;  // false for fewer than 3 points or a degenerate (collinear) set
};

// Axis-aligned bounding box, metres.
struct Bounds {
  std::array<float, 3> min_m{};
  std::array<float, 3> max_m{};
  bool empty = true;
  void add(float x, float y, float z);
  void merge(const Bounds& other);
};

// Total least squares (algo::PlaneMoments) over the points [begin, end).
FittedPlane fit_plane(const BlobSegments& points, std::int32_t begin, std::int32_t end);

Bounds bounds_of(const BlobSegments& points, std::int32_t begin, std::int32_t end);

// Points of [begin, end) more than tolerance_m in front of `plane`, and more than tolerance_m
// behind it.
std::int32_t count_in_front(const BlobSegments& points, const algo::Plane& plane,
                            std::int32_t begin, std::int32_t end, double tolerance_m);
std::int32_t count_behind(const BlobSegments& points, const algo::Plane& plane, std::int32_t begin,
                          std::int32_t end, double tolerance_m);

// Share of the points [begin, end) that are not more than tolerance_m in front of `plane`
// (1 for an empty range).
double share_not_in_front(const BlobSegments& points, const FittedPlane& plane, std::int32_t begin,
                          std::int32_t end, double tolerance_m);

// Root mean square distance of the points [begin, end) to `plane`, metres (0 for an empty range).
double plane_rms_m(const BlobSegments& points, const FittedPlane& plane, std::int32_t begin,
                   std::int32_t end);

// Cosine of the angle between two planes' normals.
double normal_cosine(const FittedPlane& a, const FittedPlane& b);

// The larger of the two centroids' distances from the other's plane, metres: with the normals'
// angle, how far two planes are from being one.
double centroid_offset_m(const FittedPlane& a, const FittedPlane& b);

// The smaller of the two: how far both stand off the other's plane. Two pieces of one face
// whose fitted normals differ a little are close by it (a tilt moves the far centroid off the
// other's plane, not the near one); two parallel faces a step apart are not.
double smaller_centroid_offset_m(const FittedPlane& a, const FittedPlane& b);

}  // namespace facet::partition
