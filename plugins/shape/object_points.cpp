#include "shape/object_points.hpp"

#include <algorithm>
#include <cmath>

#include "facet/error.hpp"
#include "facet/image_checks.hpp"

namespace facet::shape {

std::vector<ObjectPoints> gather_object_points(const cv::Mat& labels, const cv::Mat& points) {
  require_same_size(labels, "objects", points, "points");

  // Ids are dense (1..N) in practice, so a table indexed by id is cheaper than a map.
  std::vector<ObjectPoints> by_id;
  for (int v = 0; v < labels.rows; ++v) {
    const auto* label_row = labels.ptr<std::int32_t>(v);
    const auto* point_row = points.ptr<cv::Vec3f>(v);
    for (int u = 0; u < labels.cols; ++u) {
      const std::int32_t id = label_row[u];
      if (id <= 0) continue;
      if (static_cast<std::size_t>(id) >= by_id.size())
        by_id.resize(static_cast<std::size_t>(id) + 1);
      ObjectPoints& object = by_id[static_cast<std::size_t>(id)];
      object.id = id;
      ++object.pixel_count;
      const cv::Vec3f& p = point_row[u];
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) {
        object.points.emplace_back(p[0], p[1], p[2]);
      }
    }
  }
  std::vector<ObjectPoints> objects;
  for (auto& object : by_id) {
    if (object.pixel_count > 0) objects.push_back(std::move(object));
  }
  return objects;
}

}  // namespace facet::shape
