#pragma once
// World directions in the camera frame of a camera pitched down at a table, for building table
// scenes with synthetic_scene.hpp: x right, y forward (away from the camera), z up; the table
// plane passes through table_point, 1 m along the optical axis.

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "synthetic_scene.hpp"

namespace facet::test {

struct TabletopFrame {
  explicit TabletopFrame(double pitch_deg = 40.0) {
    const double a = pitch_deg * std::numbers::pi / 180.0;
    up = {0.0, -std::cos(a), -std::sin(a)};
    forward = {0.0, -std::sin(a), std::cos(a)};
  }
  Eigen::Vector3d up;
  Eigen::Vector3d forward;
  Eigen::Vector3d right{1.0, 0.0, 0.0};
  Eigen::Vector3d table_point{0.0, 0.0, 1.0};

  // A pose at (x right, y forward) on the table, lifted by `height_m` along up.
  Eigen::Isometry3d on_table(double x_m, double y_m, double height_m) const {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear().col(0) = right;
    pose.linear().col(1) = forward;
    pose.linear().col(2) = up;
    pose.translation() = table_point + x_m * right + y_m * forward + height_m * up;
    return pose;
  }
  // A box of half extents `half_m` standing on the table at (x, y).
  SceneBuilder& box_on_table(SceneBuilder& scene, double x_m, double y_m,
                             const Eigen::Vector3d& half_m) const {
    return scene.box(on_table(x_m, y_m, half_m.z()), half_m);
  }
};

}  // namespace facet::test
