#pragma once
// One plane type for the stages' geometry, and its two fits: total least squares through a set
// of points, and RANSAC over random triples of points followed by a least-squares refit to the
// best hypothesis' inliers (paper sec. II-B d). planes.support fits the support planes with
// them, the partition stages the planes of surface segments.
//
// The frame's support planes as a packet are facet::Plane (facet/types/geometry.hpp, double, with
// an id and a role); this is the working type of the fits, in float like the point images.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <random>
#include <span>

namespace facet::algo {

// n·x + d = 0 with a unit normal oriented towards the camera: the camera centre lies on the
// positive side (d ≥ 0), so a positive signed distance is in front of the surface.
struct Plane {
  Eigen::Vector3f normal = -Eigen::Vector3f::UnitZ();
  float offset_m = 0.0F;

  // The plane with this normal (unit length) through `point`, oriented towards the camera.
  static Plane through(const Eigen::Vector3f& unit_normal, const Eigen::Vector3f& point_m);

  float signed_distance_m(float x, float y, float z) const {
    return normal.x() * x + normal.y() * y + normal.z() * z + offset_m;
  }
  // xyz: three floats, metres.
  float signed_distance_m(const float* xyz) const {
    return signed_distance_m(xyz[0], xyz[1], xyz[2]);
  }
};

// A plane and two orthogonal unit axes in it.
struct PlaneFrame {
  Plane plane;
  Eigen::Vector3f axis_u = Eigen::Vector3f::UnitX();
  Eigen::Vector3f axis_v = Eigen::Vector3f::UnitY();
};

// The first and second moments of a point set, accumulated in double relative to its first
// point, so that centimetre spreads at metre range lose nothing to cancellation.
class PlaneMoments {
 public:
  // Inline: it runs once per point of every fitted segment.
  void add(float x, float y, float z) {
    const Eigen::Vector3d p(x, y, z);
    if (count_ == 0) origin_m_ = p;
    const Eigen::Vector3d d = p - origin_m_;
    sum_m_ += d;
    // The upper triangle only: plane() mirrors it.
    sum_sq_m2_(0, 0) += d.x() * d.x();
    sum_sq_m2_(0, 1) += d.x() * d.y();
    sum_sq_m2_(0, 2) += d.x() * d.z();
    sum_sq_m2_(1, 1) += d.y() * d.y();
    sum_sq_m2_(1, 2) += d.y() * d.z();
    sum_sq_m2_(2, 2) += d.z() * d.z();
    ++count_;
  }
  std::int64_t count() const { return count_; }
  // The mean of the points added (zero for none).
  Eigen::Vector3d centroid_m() const;
  // The total-least-squares plane: normal = the eigenvector of the covariance's smallest
  // eigenvalue, through the centroid. Nothing for fewer than 3 points or points spread in fewer
  // than two directions (second eigenvalue at most kMinSpread_m2: a line, one point).
  std::optional<Plane> plane() const;
  // That plane with its two in-plane axes: the directions of the points' largest and second
  // largest spread (unit, orthogonal), a rectangle's sides for the points of one.
  std::optional<PlaneFrame> frame() const;

  static constexpr double kMinSpread_m2 = 1e-10;

 private:
  std::int64_t count_ = 0;
  Eigen::Vector3d origin_m_ = Eigen::Vector3d::Zero();   // the first point
  Eigen::Vector3d sum_m_ = Eigen::Vector3d::Zero();      // of p - origin
  Eigen::Matrix3d sum_sq_m2_ = Eigen::Matrix3d::Zero();  // of (p - origin)(p - origin)ᵀ, upper
};

// xyz: interleaved points, three floats each (metres, all finite).
std::optional<Plane> least_squares_plane(std::span<const float> xyz);

struct RansacPlaneRule {
  int iterations = 20;               // hypotheses at least, each from a random triple of points
  float inlier_distance_m = 0.006F;  // a hypothesis' and the refit's inlier threshold
  int max_scored_points = 1000;      // hypotheses are scored on at most this many points
  // Adaptive stopping: more hypotheses until, at the best hypothesis' inlier share w, a triple
  // of inliers has been drawn with this probability (1 - (1 - w³)^n ≥ confidence), up to
  // max_iterations. 0 = exactly `iterations`.
  double confidence = 0.0;
  int max_iterations = 20;
};

// The hypotheses the adaptive rule asks for when the best one so far holds `inlier_share` of the
// scored points: the n with 1 - (1 - w³)^n ≥ confidence (1 for w = 1, a huge count for w → 0).
int ransac_hypotheses_needed(double inlier_share, double confidence);

// The best-supported hypothesis, refitted by least squares to its inliers. xyz as above; `rng`
// is advanced (the caller seeds it). Nothing when the points are degenerate: fewer than 3, no
// triple whose cross product reaches 1 cm², no support for any hypothesis.
std::optional<Plane> ransac_plane(std::span<const float> xyz, const RansacPlaneRule& rule,
                                  std::mt19937& rng);

}  // namespace facet::algo
