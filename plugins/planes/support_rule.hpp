#pragma once
// Which fitted candidate planes are support or background planes (table, floor, walls) and which
// are object faces (the top or side of a big box).
//
// The paper's rule (every large patch is a background plane) removes big box faces at 640x480;
// one plane from the largest patch leaves floor and walls as objects in uncropped views. Here a
// candidate is a support plane when
//   - it is the dominant horizontal plane (the largest candidate facing world up), or
//   - it covers at least `min_view_fraction` of the valid pixels AND hardly any object candidate
//     lies behind it: background planes have the scene in front of them (objects stand on a table,
//     in front of a wall), while a box face has the rest of its box (and the table) behind it.
// "Object candidates" are points on no accepted plane. The decision is iterated until nothing
// changes, so that the order of the planes does not matter: a table whose plane has the floor
// and the lower walls behind it is accepted once floor and walls are.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "facet/algo/plane.hpp"
#include "planes/scene_model.hpp"

namespace facet::planes {

struct SupportRule {
  float inlier_distance_m = 0.012F;   // delta: a point within it lies on the plane
  float behind_margin_m = 0.05F;      // a point further than this behind a plane is behind it
  double min_view_fraction = 0.01;    // of the valid pixels, on the plane
  double max_behind_fraction = 0.05;  // of the object candidate pixels, behind the plane
  double min_object_fraction = 0.02;  // of the valid pixels: floor of the behind denominator
  double max_support_behind_fraction = 0.1;  // of the dominant plane, behind a candidate
  double large_view_fraction = 0.15;  // horizontal candidates this large skip the dominant test
  double min_cos_horizontal = 0.985;  // cos(alpha_z): a normal this close to up is horizontal
  int sample_stride_px = 2;           // the evidence is gathered on every n-th row and column
};

struct CandidateEvidence {
  double view_fraction = 0.0;            // samples on the plane / valid samples
  double behind_fraction = 0.0;          // at the final decision
  double support_behind_fraction = 0.0;  // share of the dominant plane behind this one
  bool accepted = false;
};

// At most 32 candidates (one bit each per sample). `table` is the index of the table's candidate
// or -1 (scene_model.hpp); the candidates whose role is table are accepted from the start, object
// tops never, the undecided ones by the rule above. `up` is world up (unit, camera frame).
std::vector<CandidateEvidence> decide_support(const cv::Mat& points,
                                              const std::vector<algo::Plane>& candidates, int table,
                                              const std::vector<CandidateRole>& roles,
                                              const Eigen::Vector3f& up, const SupportRule& rule);

}  // namespace facet::planes
