#pragma once
// One object standing on a table, seen by a camera that looks down at it: the object's label
// image, its points and the table as a support plane, as the shape stages receive them.

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "synthetic_scene.hpp"

namespace facet::test {

struct TabletopScene {
  LabelImage objects;  // the object's pixels = 1
  PointImage points;   // every hit pixel back-projected (table too), NaN elsewhere
  SupportPlanes planes;
  Eigen::Vector3d up;             // world up in the camera frame
  Eigen::Isometry3d object_pose;  // true centre and axes (z = up)
};

enum class TabletopShape { box, cylinder };

// The camera looks down at `pitch_deg`; the object's base centre is at `base_m` on the table,
// turned by `yaw_deg` about the up axis. Box: half extents `half_m`; cylinder: radius half_m.x(),
// half height half_m.z().
inline TabletopScene render_tabletop(TabletopShape shape, const Eigen::Vector3d& half_m,
                                     double pitch_deg = 50.0, double yaw_deg = 25.0,
                                     const Eigen::Vector3d& base_m = {0.0, 0.1, 0.9}) {
  constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
  const double pitch = pitch_deg * kDegToRad;
  TabletopScene scene;
  scene.up = Eigen::Vector3d(0.0, -std::cos(pitch), -std::sin(pitch));
  const Eigen::Vector3d x0 = Eigen::Vector3d::UnitX();
  Eigen::Matrix3d axes;
  axes.col(0) = Eigen::AngleAxisd(yaw_deg * kDegToRad, scene.up) * x0;
  axes.col(2) = scene.up;
  axes.col(1) = scene.up.cross(axes.col(0));
  scene.object_pose = Eigen::Isometry3d::Identity();
  scene.object_pose.linear() = axes;
  scene.object_pose.translation() = base_m + scene.up * half_m.z();

  SceneBuilder builder;
  builder.plane(base_m, scene.up);
  if (shape == TabletopShape::box) {
    builder.box(scene.object_pose, half_m);
  } else {
    builder.cylinder(scene.object_pose, half_m.x(), half_m.z());
  }
  const RenderedScene rendered = builder.render();
  const CameraIntrinsics& camera = rendered.camera;

  scene.objects.camera = camera;
  scene.objects.labels = cv::Mat::zeros(camera.height, camera.width, CV_32SC1);
  scene.objects.count = 1;
  scene.points.camera = camera;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  scene.points.points = cv::Mat(camera.height, camera.width, CV_32FC3, cv::Scalar(nan, nan, nan));
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const float z = rendered.depth_m.at<float>(v, u);
      if (z <= 0.0f) continue;
      scene.points.points.at<cv::Vec3f>(v, u) =
          cv::Vec3f(static_cast<float>((u - camera.cx) * z / camera.fx),
                    static_cast<float>((v - camera.cy) * z / camera.fy), z);
      if (rendered.object.at<int>(v, u) == 2) scene.objects.labels.at<int>(v, u) = 1;
    }
  }
  Plane table;
  table.id = 1;
  table.normal = scene.up;
  table.offset_m = -scene.up.dot(base_m);
  table.horizontal = true;
  scene.planes.camera = camera;
  scene.planes.planes.push_back(table);
  scene.planes.up = scene.up;
  return scene;
}

}  // namespace facet::test
