#include "planes/convex_hull.hpp"

#include <algorithm>

namespace facet::planes {
namespace {

// Twice the signed area of the triangle o, a, b: positive when it turns counter-clockwise.
double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return {};
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const Eigen::Vector2d& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0)
      --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
    const Eigen::Vector2d& p = points[i - 1];
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p) <= 0.0)
      --k;
    hull[k++] = p;
  }
  hull.resize(k - 1);
  return hull.size() >= 3 ? hull : std::vector<Eigen::Vector2d>{};
}

bool inside_convex_hull(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector2d& point) {
  if (hull.size() < 3) return false;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    if (cross(hull[i], hull[(i + 1) % hull.size()], point) < 0.0) return false;
  }
  return true;
}

}  // namespace facet::planes
