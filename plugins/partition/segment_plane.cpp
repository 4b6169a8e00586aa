#include "partition/segment_plane.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace facet::partition {

void Bounds::add(float x, float y, float z) {
  if (empty) {
    min_m = {x, y, z};
    max_m = {x, y, z};
    empty = false;
    return;
  }
  min_m = {std::min(min_m[0], x), std::min(min_m[1], y), std::min(min_m[2], z)};
  max_m = {std::max(max_m[0], x), std::max(max_m[1], y), std::max(max_m[2], z)};
}

void Bounds::merge(const Bounds& other) {
  if (other.empty) return;
  add(other.min_m[0], other.min_m[1], other.min_m[2]);
  add(other.max_m[0], other.max_m[1], other.max_m[2]);
}

FittedPlane fit_plane(const BlobSegments& points, std::int32_t begin, std::int32_t end) {
  algo::PlaneMoments moments;
  for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k) {
    moments.add(points.x[k], points.y[k], points.z[k]);
  }
  FittedPlane fitted;
  const std::optional<algo::PlaneFrame> frame = moments.frame();
  if (!frame) return fitted;
  static_cast<algo::Plane&>(fitted) = frame->plane;
  fitted.axis_u = frame->axis_u;
  fitted.axis_v = frame->axis_v;
  fitted.centroid_m = moments.centroid_m().cast<float>();
  fitted.valid = true;
  return fitted;
}

Bounds bounds_of(const BlobSegments& points, std::int32_t begin, std::int32_t end) {
  Bounds box;
  for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k) {
    box.add(points.x[k], points.y[k], points.z[k]);
  }
  return box;
}

std::int32_t count_in_front(const BlobSegments& points, const algo::Plane& plane,
                            std::int32_t begin, std::int32_t end, double tolerance_m) {
  const float nx = plane.normal[0];
  const float ny = plane.normal[1];
  const float nz = plane.normal[2];
  const float d0 = plane.offset_m;
  const auto tol = static_cast<float>(tolerance_m);
  const float* x = points.x.data();
  const float* y = points.y.data();
  const float* z = points.z.data();
  std::int32_t in_front = 0;
  for (std::int32_t k = begin; k < end; ++k) {
    in_front += static_cast<std::int32_t>(nx * x[k] + ny * y[k] + nz * z[k] + d0 > tol);
  }
  return in_front;
}

std::int32_t count_behind(const BlobSegments& points, const algo::Plane& plane, std::int32_t begin,
                          std::int32_t end, double tolerance_m) {
  // Behind the plane is in front of it turned round (negating every term is exact).
  const algo::Plane turned{-plane.normal, -plane.offset_m};
  return count_in_front(points, turned, begin, end, tolerance_m);
}

double share_not_in_front(const BlobSegments& points, const FittedPlane& plane, std::int32_t begin,
                          std::int32_t end, double tolerance_m) {
  if (end <= begin) return 1.0;
  const std::int32_t in_front = count_in_front(points, plane, begin, end, tolerance_m);
  return 1.0 - static_cast<double>(in_front) / static_cast<double>(end - begin);
}

double plane_rms_m(const BlobSegments& points, const FittedPlane& plane, std::int32_t begin,
                   std::int32_t end) {
  if (end <= begin) return 0.0;
  double sum = 0.0;
  for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k) {
    const double d = plane.signed_distance_m(points.x[k], points.y[k], points.z[k]);
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(end - begin));
}

double normal_cosine(const FittedPlane& a, const FittedPlane& b) {
  return static_cast<double>(a.normal[0] * b.normal[0] + a.normal[1] * b.normal[1] +
                             a.normal[2] * b.normal[2]);
}

namespace {

// Each centroid's distance from the other's plane.
std::pair<float, float> centroid_offsets_m(const FittedPlane& a, const FittedPlane& b) {
  return {std::abs(b.signed_distance_m(a.centroid_m.data())),
          std::abs(a.signed_distance_m(b.centroid_m.data()))};
}

}  // namespace

double centroid_offset_m(const FittedPlane& a, const FittedPlane& b) {
  const auto [a_off_b, b_off_a] = centroid_offsets_m(a, b);
  return static_cast<double>(std::max(a_off_b, b_off_a));
}

double smaller_centroid_offset_m(const FittedPlane& a, const FittedPlane& b) {
  const auto [a_off_b, b_off_a] = centroid_offsets_m(a, b);
  return static_cast<double>(std::min(a_off_b, b_off_a));
}

}  // namespace facet::partition
