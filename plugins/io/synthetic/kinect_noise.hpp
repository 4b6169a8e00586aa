#pragma once
// What a Kinect v1 (structured light) makes of a perfect depth image: range limits, projector
// shadows, dropouts at depth jumps and grazing angles, axial noise growing with distance, and
// depth computed from disparity quantised to sub-pixel steps.

#include <opencv2/core/mat.hpp>

#include "synthetic/random_stream.hpp"
#include "synthetic/ray_caster.hpp"
#include "synthetic/scene.hpp"

namespace facet::synthetic {

struct KinectNoise {
  bool enabled = true;         // false: the perfect depth, rounded to mm (range still applies)
  double min_depth_m = 0.5;    // nearer: no measurement
  double max_depth_m = 4.0;    // farther: no measurement
  double ir_focal_px = 580.0;  // IR camera focal length the disparity is measured with
  double baseline_m = 0.075;   // camera to projector
  double disparity_step_px = 0.125;  // sub-pixel resolution of the disparity; 0 = none
  double axial_noise_scale = 1.0;    // times sigma_z(z) = 0.0012 + 0.0019 (z - 0.4)^2 m
  bool shadows = true;               // pixels the projector does not light get no measurement
  double jump_dropout = 0.5;         // chance of losing a pixel beside a depth jump
  double jump_min_m = 0.02;          // a depth jump: neighbours further apart than this + 1 % z
  double grazing_start_deg = 80.0;   // incidence angle from which pixels start to drop out
  double grazing_end_deg = 89.0;     // incidence angle from which every pixel drops out
  double dropout_cell_px = 4.0;      // dropouts come in blobs of about this size

  // The axial standard deviation of the measured depth at depth z and incidence angle theta
  // (between the camera ray and the surface normal), times the scale: Nguyen, Izadi, Lovell 2012,
  // sigma_z = 0.0012 + 0.0019 (z - 0.4)^2 + 0.0001 / sqrt(z) * theta^2 / (pi/2 - theta)^2 m.
  // Angles are capped at 89.5 deg, where the last term is already 0.8 m.
  double axial_sigma_m(double z_m, double incidence_rad = 0.0) const;

  // The step between neighbouring depth levels at depth z: z^2 / (f b) * disparity step.
  double depth_step_m(double z_m) const {
    return z_m * z_m / (ir_focal_px * baseline_m) * disparity_step_px;
  }
};

// Whether the projector lights the surface point: the segment from the projector to it meets no
// other surface first (else the point lies in its shadow and gets no depth).
bool lit_by_projector(const Scene& scene, const CameraRig& rig, const Vec3& point);

// Depth in millimetres (CV_16UC1, 0 = no measurement) of `frame` as the sensor delivers it.
// `random` supplies the noise; the scene is needed for the projector's view (shadows).
cv::Mat measure_depth(const IdealFrame& frame, const Scene& scene, const CameraRig& rig,
                      const KinectNoise& noise, RandomStream& random);

}  // namespace facet::synthetic
