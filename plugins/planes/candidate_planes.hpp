#pragma once
// The first kernel of planes.support: the candidate planes of a frame. Every surface patch of at
// least min_px valid points is a candidate (largest first, at most max_candidates); a plane is
// fitted to it (algo::ransac_plane). A patch may hold more than one plane: where no normal edge
// parts them (a far table running into the wall behind it, seen at a grazing angle), one patch
// spans both. What a fit leaves clearly off its plane, when it is a candidate's worth of pixels, is
// fitted again, up to planes_per_patch planes.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <random>
#include <vector>

#include "facet/algo/plane.hpp"

namespace facet::planes {

struct CandidateRule {
  std::int64_t min_px = 2500;           // a patch with this many pixels is a candidate
  int max_candidates = 16;              // the largest this many patches are fitted
  std::int64_t max_fit_points = 10000;  // points a fit sees, every k-th of the patch
  int planes_per_patch = 2;             // planes fitted to one patch at most
  float off_plane_m = 0.02F;            // a point this far from a fit is left for the next one
  float same_plane_cos = 0.985F;        // a refit this parallel and close is the same plane
};

struct CandidatePlane {
  algo::Plane model;
  std::int64_t size_px = 0;  // pixels of the patch (or, after a split, on this plane)
  Eigen::Vector3f centroid_m = Eigen::Vector3f::Zero();  // of the points fitted
  // At most kFootprintPoints of those points, evenly spread: where the plane lies, for the scene
  // model's test of whether one level lies over another.
  std::vector<Eigen::Vector3f> footprint_m;
};

inline constexpr std::size_t kFootprintPoints = 256;

// labels: CV_32SC1 patch ids 1..count, continuous; xyz: CV_32FC3 points (metres, NaN = invalid),
// continuous, same size. The planes come largest first (stable: ties keep the patch order, a
// larger patch before a smaller, a lower id before a higher). `rng` is advanced by the fits.
std::vector<CandidatePlane> find_candidate_planes(const cv::Mat& labels, const cv::Mat& xyz,
                                                  std::int32_t count, const CandidateRule& rule,
                                                  const algo::RansacPlaneRule& fit_rule,
                                                  std::mt19937& rng);

}  // namespace facet::planes
