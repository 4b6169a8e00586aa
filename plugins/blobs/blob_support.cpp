#include "blobs/blob_support.hpp"

#include <cstddef>
#include <vector>

namespace facet::blobs {

std::int32_t drop_blobs_behind_planes(EuclideanRegions& blobs, const cv::Mat& xyz,
                                      const SupportPlanes& planes, double max_behind_fraction,
                                      float margin_m) {
  if (planes.planes.empty() || blobs.count == 0) return 0;
  const std::size_t count = static_cast<std::size_t>(blobs.count) + 1;
  std::vector<std::int64_t> size_px(count, 0);
  // behind[id * planes + k]: points of blob id behind plane k.
  const std::size_t plane_count = planes.planes.size();
  std::vector<std::int64_t> behind(count * plane_count, 0);
  std::vector<Eigen::Vector4f> models;
  for (const Plane& plane : planes.planes) {
    models.emplace_back(plane.normal.cast<float>().x(), plane.normal.cast<float>().y(),
                        plane.normal.cast<float>().z(), static_cast<float>(plane.offset_m));
  }
  auto* label = blobs.labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = blobs.labels.total();
  for (std::size_t i = 0; i < total; ++i) {
    const auto id = static_cast<std::size_t>(label[i]);
    if (id == 0) continue;
    ++size_px[id];
    const float* p = point + 3 * i;
    for (std::size_t k = 0; k < plane_count; ++k) {
      const Eigen::Vector4f& m = models[k];
      if (m.x() * p[0] + m.y() * p[1] + m.z() * p[2] + m.w() < -margin_m) {
        ++behind[id * plane_count + k];
      }
    }
  }
  std::vector<std::int32_t> new_id(count, 0);
  std::int32_t kept = 0;
  for (std::size_t id = 1; id < count; ++id) {
    bool in_front = true;
    for (std::size_t k = 0; k < plane_count; ++k) {
      if (static_cast<double>(behind[id * plane_count + k]) >
          max_behind_fraction * static_cast<double>(size_px[id])) {
        in_front = false;
      }
    }
    if (in_front) new_id[id] = ++kept;
  }
  for (std::size_t i = 0; i < total; ++i)
    label[i] = new_id[static_cast<std::size_t>(label[i])];
  const std::int32_t removed = blobs.count - kept;
  blobs.count = kept;
  return removed;
}

}  // namespace facet::blobs
