// partition.graph's curvature feature: curved patches of one cup, bowl or can, e.g. the inside
// and the outside of a bowl, which meet at the rim. Their junction is concave seen from the
// camera, so the convex feature cannot join them; but both lie on one elliptic quadric (sphere,
// ellipsoid, elliptic cylinder or paraboloid), up to the wall thickness, while two touching
// round objects (two cans, a cup beside a bowl) need two. The two pieces of a can lying behind
// an occluder are fitted by a circular cylinder instead (cylinder_fit.hpp).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "partition/cylinder_fit.hpp"
#include "partition/graph_candidates.hpp"
#include "partition/graph_edges.hpp"
#include "partition/graph_gap.hpp"

namespace facet::partition {
namespace {

using Vector10 = Eigen::Matrix<double, 10, 1>;
using Matrix10 = Eigen::Matrix<double, 10, 10>;

// Monomials of a quadric in x, y, z: x², y², z², xy, xz, yz, x, y, z, 1.
Vector10 monomials(double x, double y, double z) {
  Vector10 m;
  m << x * x, y * y, z * z, x * y, x * z, y * z, x, y, z, 1.0;
  return m;
}

struct Samples {
  std::vector<Eigen::Vector3d> a;
  std::vector<Eigen::Vector3d> b;
};

void take_samples(const BlobSegments& points, const Segment& segment, std::int32_t max_samples,
                  std::vector<Eigen::Vector3d>& out) {
  out.clear();
  const std::int32_t stride = sample_stride(segment, max_samples);
  for (std::int32_t k = segment.begin; k < segment.end; k += stride) {
    const auto i = static_cast<std::size_t>(k);
    out.emplace_back(points.x[i], points.y[i], points.z[i]);
  }
}

// Share of the samples within tolerance of the quadric, by the first-order (Sampson) distance
// |Q(q)| / |grad Q(q)| in the normalised frame, times the scale back to metres.
double share_on_quadric(const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& centre,
                        double scale_m, const Vector10& q, const Eigen::Matrix3d& quadratic,
                        double tolerance_m) {
  if (samples.empty()) return 0.0;
  const Eigen::Vector3d linear(q(6), q(7), q(8));
  std::size_t on = 0;
  for (const Eigen::Vector3d& p : samples) {
    const Eigen::Vector3d x = (p - centre) / scale_m;
    const double value = monomials(x.x(), x.y(), x.z()).dot(q);
    const double gradient = (2.0 * quadratic * x + linear).norm();
    if (gradient > 1e-12 && std::abs(value) / gradient * scale_m <= tolerance_m) ++on;
  }
  return static_cast<double>(on) / static_cast<double>(samples.size());
}

// Which quadrics count: every elliptic one, or closed ones only (an ellipsoid or sphere: all three
// curvature directions bend the same way, the weakest at least rule.min_axis_ratio of the
// strongest), which leaves out cylinders.
enum class QuadricKind { elliptic, closed };

bool one_elliptic_quadric(const Samples& samples, const CurvatureRule& rule,
                          QuadricKind kind = QuadricKind::elliptic) {
  if (samples.a.size() < 10 || samples.b.size() < 10) return false;
  Eigen::Vector3d mean_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_b = Eigen::Vector3d::Zero();
  for (const auto& p : samples.a)
    mean_a += p;
  for (const auto& p : samples.b)
    mean_b += p;
  mean_a /= static_cast<double>(samples.a.size());
  mean_b /= static_cast<double>(samples.b.size());
  const Eigen::Vector3d centre = 0.5 * (mean_a + mean_b);
  double spread = 0.0;
  for (const auto& p : samples.a)
    spread += (p - centre).squaredNorm() / static_cast<double>(samples.a.size());
  for (const auto& p : samples.b)
    spread += (p - centre).squaredNorm() / static_cast<double>(samples.b.size());
  const double scale_m = std::sqrt(0.5 * spread);
  if (!(scale_m > 1e-6)) return false;

  // Algebraic least squares with |q| = 1, each patch weighted equally so that a large outside
  // does not fit the quadric to itself alone. Normalising centre and scale keeps the 10 x 10
  // system well conditioned.
  Matrix10 scatter = Matrix10::Zero();
  for (const auto* set : {&samples.a, &samples.b}) {
    const double weight = 1.0 / static_cast<double>(set->size());
    for (const Eigen::Vector3d& p : *set) {
      const Eigen::Vector3d x = (p - centre) / scale_m;
      const Vector10 m = monomials(x.x(), x.y(), x.z());
      scatter.selfadjointView<Eigen::Lower>().rankUpdate(m, weight);
    }
  }
  const Eigen::SelfAdjointEigenSolver<Matrix10> solver(
      Matrix10(scatter.selfadjointView<Eigen::Lower>()));
  if (solver.info() != Eigen::Success) return false;
  const Vector10 q = solver.eigenvectors().col(0);

  // Elliptic type: the two strongest curvature directions bend the same way. Two planes (the
  // quadric any two flat faces fit) have curvatures of opposite sign, parallel planes only one.
  Eigen::Matrix3d quadratic;
  quadratic << q(0), 0.5 * q(3), 0.5 * q(4), 0.5 * q(3), q(1), 0.5 * q(5), 0.5 * q(4), 0.5 * q(5),
      q(2);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(quadratic, Eigen::EigenvaluesOnly);
  std::array<double, 3> e{axes.eigenvalues()(0), axes.eigenvalues()(1), axes.eigenvalues()(2)};
  std::sort(e.begin(), e.end(), [](double x, double y) { return std::abs(x) > std::abs(y); });
  if (!(std::abs(e[0]) > 0.0)) return false;
  if (e[0] * e[1] <= 0.0 || std::abs(e[1]) < rule.min_axis_ratio * std::abs(e[0])) return false;
  if (e[0] * e[2] < 0.0 && std::abs(e[2]) >= rule.min_axis_ratio * std::abs(e[0])) return false;
  if (kind == QuadricKind::closed &&
      (e[0] * e[2] <= 0.0 || std::abs(e[2]) < rule.min_axis_ratio * std::abs(e[0]))) {
    return false;
  }

  return share_on_quadric(samples.a, centre, scale_m, q, quadratic, rule.tolerance_m) >=
             rule.min_share &&
         share_on_quadric(samples.b, centre, scale_m, q, quadratic, rule.tolerance_m) >=
             rule.min_share;
}

// The samples of a candidate pair's two patches. nearest_pairs returns the pairs grouped by
// their first node, so that node's samples are kept until it changes.
class PairSampler {
 public:
  PairSampler(const BlobSegments& points, const GraphNodes& graph, const cv::Mat& point_image,
              std::int32_t max_samples)
      : points_(points), graph_(graph), point_image_(point_image), max_samples_(max_samples) {}

  const Samples& points(const CandidatePair& pair) {
    if (points_of_ != pair.a) {
      take_samples(points_, segment_of(pair.a), max_samples_, samples_.a);
      points_of_ = pair.a;
    }
    take_samples(points_, segment_of(pair.b), max_samples_, samples_.b);
    return samples_;
  }

  // The points with their normals, for the cylinder: first node, second node.
  std::pair<const OrientedSamples&, const OrientedSamples&> oriented(const CandidatePair& pair) {
    if (oriented_of_ != pair.a) {
      take_oriented_samples(points_, segment_of(pair.a), point_image_, max_samples_, oriented_a_);
      oriented_of_ = pair.a;
    }
    take_oriented_samples(points_, segment_of(pair.b), point_image_, max_samples_, oriented_b_);
    return {oriented_a_, oriented_b_};
  }

 private:
  const Segment& segment_of(std::int32_t node) const {
    return points_
        .segments[static_cast<std::size_t>(graph_.nodes[static_cast<std::size_t>(node)].segment)];
  }

  const BlobSegments& points_;
  const GraphNodes& graph_;
  const cv::Mat& point_image_;
  std::int32_t max_samples_;
  Samples samples_;
  std::int32_t points_of_ = -1;  // the node whose points samples_.a holds
  OrientedSamples oriented_a_;
  OrientedSamples oriented_b_;
  std::int32_t oriented_of_ = -1;  // the node whose points oriented_a_ holds
};

// Pairs of curved patches close in 3D, or further apart up to max_occluded_gap_m.
std::vector<CandidatePair> curved_pairs(const GraphNodes& graph,
                                        const std::vector<std::int32_t>& curved,
                                        const CurvatureRule& rule) {
  std::vector<CandidatePair> pairs;
  for (std::size_t x = 0; x < curved.size(); ++x) {
    const GraphNode& a = graph.nodes[static_cast<std::size_t>(curved[x])];
    for (std::size_t y = x + 1; y < curved.size(); ++y) {
      const GraphNode& b = graph.nodes[static_cast<std::size_t>(curved[y])];
      const double gap_m = box_gap_m(a.bounds, b.bounds);
      if (gap_m <= std::max(rule.max_gap_m, rule.max_occluded_gap_m)) {
        pairs.push_back({curved[x], curved[y], gap_m});
      }
    }
  }
  return pairs;
}

// A bowl's outside seen as a band below its rim may fit a plane: each curved patch with the
// smaller planar patches of other blobs (behind the rim's depth step) close to it in 3D.
std::vector<CandidatePair> flat_rim_pairs(const GraphNodes& graph,
                                          const std::vector<std::int32_t>& curved,
                                          const CurvatureRule& rule) {
  std::vector<CandidatePair> pairs;
  for (const std::int32_t x : curved) {
    const GraphNode& a = graph.nodes[static_cast<std::size_t>(x)];
    for (std::size_t y = 0; y < graph.nodes.size(); ++y) {
      const GraphNode& b = graph.nodes[y];
      if (b.segment < 0 || !b.planar || b.blob == a.blob || b.size_px >= a.size_px) continue;
      const double gap_m = box_gap_m(a.bounds, b.bounds);
      if (gap_m <= rule.max_gap_m) pairs.push_back({x, static_cast<std::int32_t>(y), gap_m});
    }
  }
  return pairs;
}

}  // namespace

void add_curvature_edges(const BlobSegments& points, const GraphNodes& graph,
                         const FrameImages& images, const CoplanarRule& occlusion,
                         const CurvatureRule& rule, std::vector<GraphEdge>& edges) {
  std::vector<std::int32_t> curved;
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const GraphNode& node = graph.nodes[i];
    if (node.segment >= 0 && !node.planar) curved.push_back(static_cast<std::int32_t>(i));
  }
  const auto node_count = static_cast<std::int32_t>(graph.nodes.size());
  const CylinderRule cylinder{rule.tolerance_m, rule.min_share, rule.cylinder_max_radius_m};
  PairSampler curved_samples(points, graph, *images.points, rule.max_samples);
  for (const CandidatePair& pair :
       nearest_pairs(curved_pairs(graph, curved, rule), node_count, occlusion.max_partners)) {
    const GraphNode& a = graph.nodes[static_cast<std::size_t>(pair.a)];
    const GraphNode& b = graph.nodes[static_cast<std::size_t>(pair.b)];
    if (pair.gap_m > rule.max_gap_m &&
        !is_occluded(look_between(a, b, images, plane_between(a.plane, b.plane),
                                  occlusion.front_margin_m, occlusion.lines),
                     occlusion.min_gap_px, occlusion.min_front_share)) {
      continue;
    }
    if (one_elliptic_quadric(curved_samples.points(pair), rule)) {
      edges.push_back({pair.a, pair.b, EdgeFeature::curvature});
      continue;
    }
    if (!(rule.cylinder_max_radius_m > 0.0)) continue;
    const auto [oriented_a, oriented_b] = curved_samples.oriented(pair);
    if (one_circular_cylinder(oriented_a, oriented_b, cylinder)) {
      edges.push_back({pair.a, pair.b, EdgeFeature::curvature});
    }
  }
  if (!rule.flat_rims) return;
  // Closed quadrics only: a bowl is a cap of a sphere or an ellipsoid, while a can and the face
  // of a box beside it fit an elliptic cylinder.
  PairSampler flat_samples(points, graph, *images.points, rule.max_samples);
  for (const CandidatePair& pair :
       nearest_pairs(flat_rim_pairs(graph, curved, rule), node_count, occlusion.max_partners)) {
    if (one_elliptic_quadric(flat_samples.points(pair), rule, QuadricKind::closed)) {
      edges.push_back({pair.a, pair.b, EdgeFeature::curvature});
    }
  }
}

}  // namespace facet::partition
