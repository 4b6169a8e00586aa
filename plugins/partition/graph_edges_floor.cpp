// partition.graph's floor feature: the flat floor of an open container and the curved inside of
// its wall, which meet at a concave crease.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "partition/graph_edges.hpp"

namespace facet::partition {
namespace {

// How far (degrees) the points of `wall` turn around the floor's centroid, seen in the floor's
// plane: a full turn less the widest angle without a point.
double wrap_deg(const BlobSegments& points, const Segment& wall, const FittedPlane& floor,
                std::int32_t max_samples) {
  const Eigen::Vector3f& normal = floor.normal;
  // A unit vector in the plane, and the one a quarter turn from it.
  const Eigen::Vector3f seed =
      std::abs(normal.x()) < 0.9F ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  const Eigen::Vector3f e1 = normal.cross(seed).normalized();
  const Eigen::Vector3f e2 = normal.cross(e1);
  const std::int32_t stride = std::max(1, wall.size() / std::max(max_samples, 1));
  std::vector<double> angles;
  angles.reserve(static_cast<std::size_t>(wall.size() / stride + 1));
  for (std::int32_t k = wall.begin; k < wall.end; k += stride) {
    const auto i = static_cast<std::size_t>(k);
    const Eigen::Vector3f d =
        Eigen::Vector3f(points.x[i], points.y[i], points.z[i]) - floor.centroid_m;
    angles.push_back(std::atan2(static_cast<double>(d.dot(e2)), static_cast<double>(d.dot(e1))));
  }
  if (angles.size() < 2) return 0.0;
  std::sort(angles.begin(), angles.end());
  double widest_gap = angles.front() + 2.0 * std::numbers::pi - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k)
    widest_gap = std::max(widest_gap, angles[k] - angles[k - 1]);
  return (2.0 * std::numbers::pi - widest_gap) * 180.0 / std::numbers::pi;
}

// Whether the floor's own patch is seen at its mean pixel: a ring of a face around something in
// front of it (a box's face around a can) has its mean pixel on that something.
bool centre_is_its_own(const GraphNode& floor, const FrameImages& images) {
  const cv::Mat& patches = *images.patches;
  const int u = static_cast<int>(std::lround(floor.centre_u_px));
  const int v = static_cast<int>(std::lround(floor.centre_v_px));
  if (u < 0 || v < 0 || u >= patches.cols || v >= patches.rows) return false;
  return patches.at<std::int32_t>(v, u) == floor.patch;
}

}  // namespace

void add_floor_edges(const BlobSegments& points, const GraphNodes& graph, const FrameImages& images,
                     const TouchingNodes& touching, const FloorRule& rule,
                     std::vector<GraphEdge>& edges) {
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const GraphNode& floor = graph.nodes[i];
    if (floor.segment < 0 || !floor.planar || !floor.plane.valid) continue;
    bool centre_checked = false;
    for (const std::int32_t j : touching[i]) {
      const GraphNode& wall = graph.nodes[static_cast<std::size_t>(j)];
      if (wall.segment < 0 || wall.planar || wall.blob != floor.blob || !wall.plane.valid) continue;
      // The inside of a container's wall, seen from above, is larger than its floor; a face
      // that a body in front of it wraps (seen at a slant, a cup before a box's face wraps it in
      // the face's plane) is in these scenes the larger one.
      if (floor.size_px >= wall.size_px) continue;
      const double rise_m = floor.plane.signed_distance_m(wall.plane.centroid_m.data());
      if (rise_m < rule.min_rise_m) continue;
      if (!centre_checked) {
        if (!centre_is_its_own(floor, images)) break;
        centre_checked = true;
      }
      const Segment& segment = points.segments[static_cast<std::size_t>(wall.segment)];
      if (wrap_deg(points, segment, floor.plane, rule.max_samples) < rule.min_wrap_deg) continue;
      const auto a = static_cast<std::int32_t>(i);
      edges.push_back({std::min(a, j), std::max(a, j), EdgeFeature::floor});
    }
  }
}

}  // namespace facet::partition
