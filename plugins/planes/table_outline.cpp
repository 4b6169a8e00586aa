#include "planes/table_outline.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "planes/convex_hull.hpp"

namespace facet::planes {
namespace {

using Point2 = Eigen::Vector2d;

}  // namespace

std::vector<Eigen::Vector3d> table_outline(const cv::Mat& plane_labels, const cv::Mat& patch_labels,
                                           const std::vector<char>& table_patches,
                                           const cv::Mat& xyz, const std::vector<char>& table_ids,
                                           const algo::Plane& table, const Eigen::Vector3f& up,
                                           int stride_px) {
  // A right-handed basis of the table plane, seen from above: e1 x e2 = n (n faces up).
  const Eigen::Vector3d n = table.normal.cast<double>();
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = n.cross(helper).normalized();
  const Eigen::Vector3d e2 = n.cross(e1);
  const bool flip = n.dot(up.cast<double>()) < 0.0;  // keep counter-clockwise seen from above
  const Eigen::Vector3d origin = -static_cast<double>(table.offset_m) * n;

  std::vector<Point2> projected;
  const int stride = std::max(1, stride_px);
  for (int row = 0; row < plane_labels.rows; row += stride) {
    const auto* id = plane_labels.ptr<std::int32_t>(row);
    const auto* patch = patch_labels.ptr<std::int32_t>(row);
    const auto* p = xyz.ptr<float>(row);
    for (int col = 0; col < plane_labels.cols; col += stride) {
      const auto plane = static_cast<std::size_t>(id[col]);
      if (plane == 0 || plane >= table_ids.size() || table_ids[plane] == 0) continue;
      const auto slot = static_cast<std::size_t>(std::max(0, patch[col]));
      if (slot >= table_patches.size() || table_patches[slot] == 0) continue;
      const Eigen::Vector3d point(p[3 * col], p[3 * col + 1], p[3 * col + 2]);
      const Eigen::Vector3d offset = point - origin;
      projected.emplace_back(offset.dot(e1), flip ? -offset.dot(e2) : offset.dot(e2));
    }
  }
  std::vector<Eigen::Vector3d> outline;
  for (const Point2& q : convex_hull(std::move(projected))) {
    outline.push_back(origin + q.x() * e1 + (flip ? -q.y() : q.y()) * e2);
  }
  return outline;
}

}  // namespace facet::planes
