#include "synthetic/kinect_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace facet::synthetic {
namespace {

// Incidence angle, in degrees, between a surface normal and the ray that reaches it.
double incidence_deg(const Vec3& normal, const Vec3& ray_direction) {
  const double cosine = std::abs(normal.dot(ray_direction)) / cv::norm(ray_direction);
  return std::acos(std::clamp(cosine, 0.0, 1.0)) * 180.0 / std::numbers::pi;
}

// Whether a 4-neighbour of (u, v) lies across a depth jump (or has no surface at all).
bool beside_jump(const cv::Mat& depth_m, int u, int v, double jump_min_m) {
  const double z = depth_m.at<double>(v, u);
  const double limit = jump_min_m + 0.01 * z;
  constexpr int du[] = {1, -1, 0, 0};
  constexpr int dv[] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int nu = u + du[k];
    const int nv = v + dv[k];
    if (nu < 0 || nv < 0 || nu >= depth_m.cols || nv >= depth_m.rows) continue;
    const double other = depth_m.at<double>(nv, nu);
    if (other <= 0.0 || std::abs(other - z) > limit) return true;
  }
  return false;
}

// A smooth random field in [0, 1]: uniform values on a grid of `cell_px` cells, interpolated
// bilinearly. Dropouts where it falls below a probability come in blobs of about a cell, as the
// Kinect's do (its disparity is matched over windows of several pixels), instead of isolated
// pinholes; where the probability is 1/2 exactly half the pixels drop out, by symmetry.
cv::Mat dropout_field(cv::Size size, double cell_px, RandomStream& random) {
  const int grid_w = static_cast<int>(std::ceil(size.width / cell_px)) + 2;
  const int grid_h = static_cast<int>(std::ceil(size.height / cell_px)) + 2;
  cv::Mat grid(grid_h, grid_w, CV_64FC1);
  for (int j = 0; j < grid_h; ++j) {
    for (int i = 0; i < grid_w; ++i)
      grid.at<double>(j, i) = random.uniform();
  }
  cv::Mat field(size, CV_64FC1);
  for (int v = 0; v < size.height; ++v) {
    const double gv = v / cell_px;
    const int j = static_cast<int>(gv);
    const double fv = gv - j;
    for (int u = 0; u < size.width; ++u) {
      const double gu = u / cell_px;
      const int i = static_cast<int>(gu);
      const double fu = gu - i;
      const double top = (1 - fu) * grid.at<double>(j, i) + fu * grid.at<double>(j, i + 1);
      const double bottom =
          (1 - fu) * grid.at<double>(j + 1, i) + fu * grid.at<double>(j + 1, i + 1);
      field.at<double>(v, u) = (1 - fv) * top + fv * bottom;
    }
  }
  return field;
}

std::uint16_t to_millimetres(double z_m) {
  return static_cast<std::uint16_t>(std::clamp(std::lround(z_m * 1000.0), 0L, 65535L));
}

}  // namespace

bool lit_by_projector(const Scene& scene, const CameraRig& rig, const Vec3& point) {
  const Ray ray{rig.projector_position, point - rig.projector_position};
  // t = 1 is the point itself; stop a little before it so that its own surface does not count.
  return !first_hit(scene, ray, 1e-6, 1.0 - 1e-4);
}

double KinectNoise::axial_sigma_m(double z_m, double incidence_rad) const {
  constexpr double kMaxAngle = 89.5 * std::numbers::pi / 180.0;
  const double theta = std::clamp(incidence_rad, 0.0, kMaxAngle);
  const double lateral = std::numbers::pi / 2.0 - theta;
  return axial_noise_scale * (0.0012 + 0.0019 * (z_m - 0.4) * (z_m - 0.4) +
                              0.0001 / std::sqrt(z_m) * theta * theta / (lateral * lateral));
}

cv::Mat measure_depth(const IdealFrame& frame, const Scene& scene, const CameraRig& rig,
                      const KinectNoise& noise, RandomStream& random) {
  cv::Mat depth_mm = cv::Mat::zeros(frame.depth_m.size(), CV_16UC1);
  const double disparity_scale = noise.ir_focal_px * noise.baseline_m;  // disparity = this / z
  const double cell_px = std::max(noise.dropout_cell_px, 1.0);
  const cv::Mat jump_field = dropout_field(depth_mm.size(), cell_px, random);
  const cv::Mat grazing_field = dropout_field(depth_mm.size(), cell_px, random);
  for (int v = 0; v < frame.depth_m.rows; ++v) {
    const auto* depth = frame.depth_m.ptr<double>(v);
    const auto* points = frame.points.ptr<cv::Vec3d>(v);
    const auto* normals = frame.normals.ptr<cv::Vec3d>(v);
    auto* out = depth_mm.ptr<std::uint16_t>(v);
    for (int u = 0; u < frame.depth_m.cols; ++u) {
      const double z = depth[u];
      if (z < noise.min_depth_m || z > noise.max_depth_m) continue;
      if (!noise.enabled) {
        out[u] = to_millimetres(z);
        continue;
      }
      // Every measurable pixel draws its variate, so that one pixel's fate does not shift the
      // noise of all the pixels after it.
      const double gaussian = random.normal();
      const double dropout_draw = jump_field.at<double>(v, u);
      const double grazing_draw = grazing_field.at<double>(v, u);

      if (noise.shadows && !lit_by_projector(scene, rig, points[u])) continue;
      if (noise.jump_dropout > 0.0 && beside_jump(frame.depth_m, u, v, noise.jump_min_m) &&
          dropout_draw < noise.jump_dropout)
        continue;
      // The worse of the two angles: the camera's view and the projector's light.
      const double camera_angle = incidence_deg(normals[u], points[u] - rig.position);
      const double angle =
          std::max(camera_angle, incidence_deg(normals[u], points[u] - rig.projector_position));
      if (angle >= noise.grazing_start_deg) {
        const double span = std::max(noise.grazing_end_deg - noise.grazing_start_deg, 1e-9);
        if (grazing_draw < (angle - noise.grazing_start_deg) / span) continue;
      }

      // Nguyen et al. measured sigma_z on real, already quantised Kinect depth: the noise added
      // before quantising is what quantisation (a uniform error of one step, variance step^2 / 12)
      // leaves of it, so that the depth delivered has the model's sigma_z.
      const double sigma_m = noise.axial_sigma_m(z, camera_angle * std::numbers::pi / 180.0);
      const double step_m = noise.depth_step_m(z);
      const double added_m = std::sqrt(std::max(sigma_m * sigma_m - step_m * step_m / 12.0, 0.0));
      double measured = z + added_m * gaussian;
      if (noise.disparity_step_px > 0.0) {
        const double disparity = disparity_scale / measured;
        const double quantised = std::max(std::round(disparity / noise.disparity_step_px), 1.0) *
                                 noise.disparity_step_px;
        measured = disparity_scale / quantised;
      }
      if (measured < noise.min_depth_m || measured > noise.max_depth_m) continue;
      out[u] = to_millimetres(measured);
    }
  }
  return depth_mm;
}

}  // namespace facet::synthetic
