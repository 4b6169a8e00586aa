#pragma once
// A table-top scene: the camera that sees it, the IR projector beside the camera, and the solids
// (table, floor, optional wall: label 0; objects: labels 1..N).

#include <vector>

#include "facet/types/frame.hpp"
#include "synthetic/primitives.hpp"

namespace facet::synthetic {

// Where the depth camera is and how it sees. World frame: z up, table top z = 0, the camera
// looks along +y and down at the table point `look_at`.
struct CameraRig {
  CameraIntrinsics intrinsics;
  Vec3 position;
  Mat3 rotation;  // camera (x right, y down, z forward) to world
  Vec3 projector_position;

  // Camera `distance_m` from `look_at`, optical axis `tilt_deg` below the horizontal, the
  // projector `projector_offset_m` to the camera's right (+x in the image).
  static CameraRig looking_at(const CameraIntrinsics& intrinsics, const Vec3& look_at,
                              double distance_m, double tilt_deg, double projector_offset_m);

  // The camera ray through pixel (u, v): its t is the depth along the optical axis.
  Ray pixel_ray(double u, double v) const;
  Vec3 to_camera(const Vec3& world) const { return rotation.t() * (world - position); }
};

struct SceneSolid {
  Solid solid;
  int label = 0;  // 0 = table, floor, wall; 1..N = object
};

struct Scene {
  std::vector<SceneSolid> solids;
  int object_count = 0;
};

struct SceneHit {
  RayHit hit;
  int label = 0;
};

// The first solid the ray meets with t in (t_min, t_max).
std::optional<SceneHit> first_hit(const Scene& scene, const Ray& ray, double t_min, double t_max);

}  // namespace facet::synthetic
