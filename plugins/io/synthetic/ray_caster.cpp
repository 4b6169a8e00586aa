#include "synthetic/ray_caster.hpp"

namespace facet::synthetic {

IdealFrame render_ideal(const Scene& scene, const CameraRig& rig, double max_depth_m) {
  const int width = rig.intrinsics.width;
  const int height = rig.intrinsics.height;
  IdealFrame frame;
  frame.depth_m = cv::Mat::zeros(height, width, CV_64FC1);
  frame.labels = cv::Mat::zeros(height, width, CV_32SC1);
  frame.points = cv::Mat::zeros(height, width, CV_64FC3);
  frame.normals = cv::Mat::zeros(height, width, CV_64FC3);
  for (int v = 0; v < height; ++v) {
    auto* depth = frame.depth_m.ptr<double>(v);
    auto* labels = frame.labels.ptr<std::int32_t>(v);
    auto* points = frame.points.ptr<cv::Vec3d>(v);
    auto* normals = frame.normals.ptr<cv::Vec3d>(v);
    for (int u = 0; u < width; ++u) {
      const Ray ray = rig.pixel_ray(u, v);
      const auto hit = first_hit(scene, ray, 0.0, max_depth_m);
      if (!hit) continue;
      depth[u] = hit->hit.t;
      labels[u] = hit->label;
      points[u] = ray.origin + hit->hit.t * ray.direction;
      normals[u] = hit->hit.normal;
    }
  }
  return frame;
}

std::vector<int> visible_pixels(const IdealFrame& frame, int object_count) {
  std::vector<int> counts(static_cast<std::size_t>(object_count) + 1, 0);
  for (int v = 0; v < frame.labels.rows; ++v) {
    const auto* labels = frame.labels.ptr<std::int32_t>(v);
    const auto* depth = frame.depth_m.ptr<double>(v);
    for (int u = 0; u < frame.labels.cols; ++u) {
      if (depth[u] > 0.0 && labels[u] >= 0 && labels[u] <= object_count) ++counts[labels[u]];
    }
  }
  return counts;
}

}  // namespace facet::synthetic
