#include "blobs/table_footprint.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace facet::blobs {

TableFootprint::TableFootprint(const SupportPlanes& planes, float margin_m) : margin_m_(margin_m) {
  const Plane* table = planes.table();
  const auto& outline = planes.table_outline_m;
  if (table == nullptr || outline.size() < 3) return;
  // Any basis of the plane will do; the sign of the polygon's area says which way it turns.
  const Eigen::Vector3f n = table->normal.cast<float>();
  const Eigen::Vector3f helper =
      std::abs(n.x()) < 0.9F ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  e1_ = n.cross(helper).normalized();
  e2_ = n.cross(e1_);
  origin_ = outline.front().cast<float>();
  std::vector<Eigen::Vector2f> corners;
  for (const Eigen::Vector3d& vertex : outline) {
    const Eigen::Vector3f offset = vertex.cast<float>() - origin_;
    corners.emplace_back(offset.dot(e1_), offset.dot(e2_));
  }
  double twice_area = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % corners.size()];
    twice_area += static_cast<double>(a.x()) * b.y() - static_cast<double>(b.x()) * a.y();
  }
  const float turn = twice_area >= 0.0 ? 1.0F : -1.0F;  // +1: counter-clockwise
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2f along = corners[(i + 1) % corners.size()] - corners[i];
    const float length = along.norm();
    if (!(length > 0.0F)) continue;
    edges_.push_back(Edge{corners[i], turn * Eigen::Vector2f(-along.y(), along.x()) / length});
  }
}

bool TableFootprint::contains(const float* xyz) const {
  const Eigen::Vector3f offset = Eigen::Vector3f(xyz[0], xyz[1], xyz[2]) - origin_;
  const Eigen::Vector2f q(offset.dot(e1_), offset.dot(e2_));
  for (const Edge& edge : edges_) {
    if ((q - edge.start).dot(edge.inward) < -margin_m_) return false;
  }
  return !edges_.empty();
}

}  // namespace facet::blobs
