#include "partition/graph_span_split.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <optional>
#include <utility>

namespace facet::partition {

namespace {

// In the plane across the pair's common normal: the normal's component is left out.
struct Seam {
  Eigen::Vector3d centroid;
  Eigen::Vector3d direction;  // unit
};

// Adds the points of segment `from` that have a pixel of patch `to` among their 8 neighbours,
// projected onto the plane through the origin with unit normal `normal` (the pair's step across
// it would otherwise widen the seam).
void add_seam_points(const BlobSegments& points, const Segment& from, std::int32_t to,
                     const cv::Mat& patches, const Eigen::Vector3d& normal,
                     std::vector<Eigen::Vector3d>& seam) {
  const int cols = patches.cols;
  const int rows = patches.rows;
  const auto* labels = patches.ptr<std::int32_t>();
  for (std::int32_t k = from.begin; k < from.end; ++k) {
    const std::int32_t pixel = points.pixel[static_cast<std::size_t>(k)];
    const int u = pixel % cols;
    const int v = pixel / cols;
    bool touches = false;
    for (int dv = -1; dv <= 1 && !touches; ++dv) {
      for (int du = -1; du <= 1 && !touches; ++du) {
        const int uu = u + du;
        const int vv = v + dv;
        if (uu < 0 || vv < 0 || uu >= cols || vv >= rows) continue;
        touches = labels[static_cast<std::size_t>(vv) * static_cast<std::size_t>(cols) +
                         static_cast<std::size_t>(uu)] == to;
      }
    }
    if (!touches) continue;
    const auto i = static_cast<std::size_t>(k);
    const Eigen::Vector3d p(points.x[i], points.y[i], points.z[i]);
    seam.push_back(p - normal * normal.dot(p));
  }
}

// The line along which the two faces of a step pair meet, or nothing when their contact is no
// line (fewer than 6 points, or spread as much across as along).
std::optional<Seam> seam_between(const BlobSegments& points, const GraphNode& a, const GraphNode& b,
                                 const cv::Mat& patches, const Eigen::Vector3d& normal,
                                 double min_elongation) {
  std::vector<Eigen::Vector3d> seam;
  add_seam_points(points, points.segments[static_cast<std::size_t>(a.segment)], b.patch, patches,
                  normal, seam);
  add_seam_points(points, points.segments[static_cast<std::size_t>(b.segment)], a.patch, patches,
                  normal, seam);
  if (seam.size() < 6) return std::nullopt;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : seam)
    mean += p;
  mean /= static_cast<double>(seam.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : seam)
    scatter += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  // Ascending eigenvalues: the largest spread is the line's, the second its width.
  const double along = eigen.eigenvalues()(2);
  const double across = eigen.eigenvalues()(1);
  if (along <= 0.0 || along < min_elongation * min_elongation * across) return std::nullopt;
  return Seam{mean, eigen.eigenvectors().col(2)};
}

std::int32_t convex_contact(std::span<const GraphEdge> edges, std::int32_t a, std::int32_t b) {
  for (const GraphEdge& edge : edges) {
    if (edge.feature == EdgeFeature::convex &&
        ((edge.a == a && edge.b == b) || (edge.a == b && edge.b == a))) {
      return std::max(edge.contact_px, 1);
    }
  }
  return 0;
}

}  // namespace

std::vector<SpanSplit> find_span_splits(const BlobSegments& points, const GraphNodes& graph,
                                        const cv::Mat& patches, std::span<const GraphEdge> edges,
                                        const StepPairs& steps, std::span<const std::int32_t> group,
                                        const SpanSplitRule& rule) {
  std::vector<SpanSplit> splits;
  if (!rule.enabled) return splits;
  std::vector<char> split(graph.nodes.size(), 0);
  for (const auto& [a, b] : steps) {
    const std::int32_t group_a = group[static_cast<std::size_t>(a)];
    const std::int32_t group_b = group[static_cast<std::size_t>(b)];
    if (group_a == group_b) continue;
    const GraphNode& node_a = graph.nodes[static_cast<std::size_t>(a)];
    const GraphNode& node_b = graph.nodes[static_cast<std::size_t>(b)];
    // The pair's common normal; its seam is measured in the plane across it.
    const Eigen::Vector3d normal =
        (node_a.plane.normal + node_b.plane.normal).cast<double>().normalized();
    std::optional<Seam> seam;
    bool seam_read = false;
    for (const GraphEdge& edge : edges) {
      if (edge.feature != EdgeFeature::convex || (edge.a != a && edge.b != a)) continue;
      const std::int32_t face = edge.a == a ? edge.b : edge.a;
      const GraphNode& node = graph.nodes[static_cast<std::size_t>(face)];
      const std::int32_t face_group = group[static_cast<std::size_t>(face)];
      if (split[static_cast<std::size_t>(face)] != 0 || !node.planar || node.segment < 0 ||
          (face_group != group_a && face_group != group_b)) {
        continue;
      }
      const std::int32_t contact_a = std::max(edge.contact_px, 1);
      const std::int32_t contact_b = convex_contact(edges, b, face);
      if (contact_b == 0 || std::min(contact_a, contact_b) <
                                rule.min_contact_ratio * std::max(contact_a, contact_b)) {
        continue;
      }
      if (!seam_read) {
        seam = seam_between(points, node_a, node_b, patches, normal, rule.min_seam_elongation);
        seam_read = true;
      }
      if (!seam) break;
      // The plane through the seam along the common normal.
      const Eigen::Vector3d across = seam->direction.cross(normal);
      if (across.norm() < 0.5) continue;  // the seam runs along the normal: no such plane
      const Eigen::Vector3f side_normal = across.normalized().cast<float>();
      const auto offset = static_cast<float>(-across.normalized().dot(seam->centroid));
      const Eigen::Vector3f& centroid_a = node_a.plane.centroid_m;
      const Eigen::Vector3f& centroid_b = node_b.plane.centroid_m;
      SpanSplit parts{face, side_normal, offset, group_a, group_b};
      const bool a_in_front = parts.in_front(centroid_a.x(), centroid_a.y(), centroid_a.z());
      if (a_in_front == parts.in_front(centroid_b.x(), centroid_b.y(), centroid_b.z())) continue;
      if (!a_in_front) std::swap(parts.group_in_front, parts.group_behind);
      const Segment& segment = points.segments[static_cast<std::size_t>(node.segment)];
      std::int32_t in_front = 0;
      for (std::int32_t k = segment.begin; k < segment.end; ++k) {
        const auto i = static_cast<std::size_t>(k);
        if (parts.in_front(points.x[i], points.y[i], points.z[i])) ++in_front;
      }
      const double share_in_front =
          static_cast<double>(in_front) / static_cast<double>(std::max(segment.size(), 1));
      if (std::min(share_in_front, 1.0 - share_in_front) < rule.min_side_share) continue;
      splits.push_back(parts);
      split[static_cast<std::size_t>(face)] = 1;
    }
  }
  return splits;
}

}  // namespace facet::partition
