#include "shape/support_plane.hpp"

#include <algorithm>
#include <cmath>

namespace facet::shape {

const Plane* find_support_plane(const std::vector<Eigen::Vector3d>& points_m,
                                const std::vector<Plane>& planes, double tolerance_m,
                                double max_gap_m) {
  if (points_m.empty()) return nullptr;
  const Plane* best = nullptr;
  double best_gap_m = 0.0;
  std::vector<double> distances(points_m.size());
  for (const Plane& plane : planes) {
    for (std::size_t i = 0; i < points_m.size(); ++i) {
      distances[i] = plane.signed_distance_m(points_m[i]);
    }
    const auto low = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 50);
    std::nth_element(distances.begin(), low, distances.end());
    const double lowest_m = *low;
    const auto mid = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
    std::nth_element(distances.begin(), mid, distances.end());
    const double median_m = *mid;
    const double gap_m = std::abs(lowest_m);
    if (median_m <= 0.0 || lowest_m < -tolerance_m) continue;
    const bool contact = gap_m <= tolerance_m;
    const bool stands_on = plane.horizontal && lowest_m <= max_gap_m;
    if (!contact && !stands_on) continue;
    if (best == nullptr || gap_m < best_gap_m) {
      best = &plane;
      best_gap_m = gap_m;
    }
  }
  return best;
}

}  // namespace facet::shape
