#include "synthetic/scene.hpp"

#include <cmath>
#include <numbers>

namespace facet::synthetic {

CameraRig CameraRig::looking_at(const CameraIntrinsics& intrinsics, const Vec3& look_at,
                                double distance_m, double tilt_deg, double projector_offset_m) {
  const double tilt = tilt_deg * std::numbers::pi / 180.0;
  const Vec3 forward(0.0, std::cos(tilt), -std::sin(tilt));
  const Vec3 right(1.0, 0.0, 0.0);
  const Vec3 down = forward.cross(right);
  CameraRig rig;
  rig.intrinsics = intrinsics;
  rig.position = look_at - distance_m * forward;
  rig.rotation = Mat3(right[0], down[0], forward[0], right[1], down[1], forward[1], right[2],
                      down[2], forward[2]);
  rig.projector_position = rig.position + projector_offset_m * right;
  return rig;
}

Ray CameraRig::pixel_ray(double u, double v) const {
  const Vec3 in_camera((u - intrinsics.cx) / intrinsics.fx, (v - intrinsics.cy) / intrinsics.fy,
                       1.0);
  return Ray{position, rotation * in_camera};
}

std::optional<SceneHit> first_hit(const Scene& scene, const Ray& ray, double t_min, double t_max) {
  std::optional<SceneHit> best;
  for (const SceneSolid& item : scene.solids) {
    const double limit = best ? best->hit.t : t_max;
    if (const auto hit = item.solid.intersect(ray, t_min, limit)) best = SceneHit{*hit, item.label};
  }
  return best;
}

}  // namespace facet::synthetic
