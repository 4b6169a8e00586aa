#include "partition/graph_gap.hpp"

#include <algorithm>
#include <cmath>

namespace facet::partition {
namespace {

// Width of an image box across the unit direction (pu, pv), pixels.
double width_across(const std::array<std::int32_t, 4>& box, double pu, double pv) {
  return std::abs(pu) * (box[2] - box[0] + 1) + std::abs(pv) * (box[3] - box[1] + 1);
}

// At least one line through, min_gap_px valid gap pixels, and min_front_share of them occluding.
bool occluded_by(const GapEvidence& gap, std::int32_t occluding_px, std::int32_t min_gap_px,
                 double min_front_share) {
  const std::int32_t valid = gap.front_px + gap.own_front_px + gap.other_px;
  return gap.lines_through > 0 && valid >= min_gap_px && valid > 0 &&
         static_cast<double>(occluding_px) >= min_front_share * valid;
}

}  // namespace

FittedPlane plane_between(const FittedPlane& a, const FittedPlane& b) {
  FittedPlane plane;
  const double nx = a.normal[0] + b.normal[0];
  const double ny = a.normal[1] + b.normal[1];
  const double nz = a.normal[2] + b.normal[2];
  const double norm = std::sqrt(nx * nx + ny * ny + nz * nz);
  if (norm <= 0.0) return a;
  plane.normal = {static_cast<float>(nx / norm), static_cast<float>(ny / norm),
                  static_cast<float>(nz / norm)};
  for (std::size_t k = 0; k < 3; ++k) {
    plane.centroid_m[k] = 0.5F * (a.centroid_m[k] + b.centroid_m[k]);
  }
  plane.offset_m = -(plane.normal[0] * plane.centroid_m[0] + plane.normal[1] * plane.centroid_m[1] +
                     plane.normal[2] * plane.centroid_m[2]);
  plane.valid = true;
  return plane;
}

bool is_occluded(const GapEvidence& gap, std::int32_t min_gap_px, double min_front_share) {
  return occluded_by(gap, gap.front_px, min_gap_px, min_front_share);
}

bool is_occluded_by_own_body(const GapEvidence& gap, std::int32_t min_gap_px,
                             double min_front_share) {
  return occluded_by(gap, gap.front_px + gap.own_front_px, min_gap_px, min_front_share);
}

GapEvidence look_between(const GraphNode& a, const GraphNode& b, const FrameImages& images,
                         const FittedPlane& surface, double front_margin_m, std::int32_t lines,
                         bool list_body_patches) {
  GapEvidence evidence;
  const cv::Mat& patches = *images.patches;
  const cv::Mat& points = *images.points;
  const int width = patches.cols;
  const int height = patches.rows;
  const auto* patch_at = patches.ptr<std::int32_t>();
  const auto* point_at = points.ptr<cv::Vec3f>();
  const auto* blob_at = images.blobs->ptr<std::int32_t>();
  const double du = b.centre_u_px - a.centre_u_px;
  const double dv = b.centre_v_px - a.centre_v_px;
  const double length = std::hypot(du, dv);
  if (length < 1.0) return evidence;
  const double pu = -dv / length;
  const double pv = du / length;
  // The lines beside the central one cover the middle 60 % of the narrower patch, so that all of
  // them start in a and end in b when the patches are roughly convex.
  const double half_span =
      0.3 * std::min(width_across(a.box_px, pu, pv), width_across(b.box_px, pu, pv));
  const auto steps = static_cast<std::int32_t>(std::ceil(length));
  const std::int32_t count = std::max<std::int32_t>(lines, 1);
  for (std::int32_t line = 0; line < count; ++line) {
    const double offset =
        count == 1 ? 0.0 : half_span * (2.0 * line / static_cast<double>(count - 1) - 1.0);
    // First pass: the last pixel of a before the first pixel of b after it.
    std::int32_t last_a = -1;
    std::int32_t first_b = -1;
    for (std::int32_t k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      const auto u = static_cast<int>(std::lround(a.centre_u_px + t * du + offset * pu));
      const auto v = static_cast<int>(std::lround(a.centre_v_px + t * dv + offset * pv));
      if (u < 0 || v < 0 || u >= width || v >= height) continue;
      const std::int32_t label = patch_at[v * width + u];
      if (label == a.patch) last_a = k;
      if (label == b.patch && last_a >= 0) {
        first_b = k;
        break;
      }
    }
    if (last_a < 0 || first_b < 0) continue;
    ++evidence.lines_through;
    for (std::int32_t k = last_a + 1; k < first_b; ++k) {
      const double t = static_cast<double>(k) / steps;
      const auto u = static_cast<int>(std::lround(a.centre_u_px + t * du + offset * pu));
      const auto v = static_cast<int>(std::lround(a.centre_v_px + t * dv + offset * pv));
      if (u < 0 || v < 0 || u >= width || v >= height) continue;
      const cv::Vec3f& p = point_at[v * width + u];
      if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
        ++evidence.invalid_px;
        continue;
      }
      const double distance = surface.signed_distance_m(p[0], p[1], p[2]);
      const std::int32_t blob = blob_at[v * width + u];
      if (distance <= front_margin_m) {
        ++evidence.other_px;
      } else if (blob != a.blob && blob != b.blob) {
        ++evidence.front_px;
      } else {
        ++evidence.own_front_px;
        const std::int32_t label = patch_at[v * width + u];
        if (list_body_patches && label > 0 && label != a.patch && label != b.patch) {
          evidence.body_patches.push_back(label);
        }
      }
    }
  }
  std::sort(evidence.body_patches.begin(), evidence.body_patches.end());
  evidence.body_patches.erase(
      std::unique(evidence.body_patches.begin(), evidence.body_patches.end()),
      evidence.body_patches.end());
  return evidence;
}

}  // namespace facet::partition
