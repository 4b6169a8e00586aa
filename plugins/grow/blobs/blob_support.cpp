#include "blobs/blob_support.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

#include "blobs/table_footprint.hpp"

namespace facet::blobs {

DroppedBlobs drop_background_blobs(EuclideanRegions& blobs, const cv::Mat& xyz,
                                   const SupportPlanes& planes, const BackgroundBlobRule& rule) {
  DroppedBlobs dropped;
  if (planes.planes.empty() || blobs.count == 0) return dropped;
  const std::size_t count = static_cast<std::size_t>(blobs.count) + 1;
  std::vector<std::int64_t> size_px(count, 0);
  std::vector<std::int64_t> on_plane_px(count, 0);  // within the band of some plane
  // behind[id * planes + k]: points of blob id behind plane k.
  const std::size_t plane_count = planes.planes.size();
  std::vector<std::int64_t> behind(count * plane_count, 0);
  std::vector<Eigen::Vector4f> models;
  std::vector<char> horizontal_support;  // the table's level and the floor: raised points stay
  for (const Plane& plane : planes.planes) {
    const Eigen::Vector3f normal = plane.normal.cast<float>();
    models.emplace_back(normal.x(), normal.y(), normal.z(), static_cast<float>(plane.offset_m));
    horizontal_support.push_back(plane.role != PlaneRole::wall ? 1 : 0);
  }
  // The table tests: points above the table, and a sample of the footprint (every 4th pixel).
  const Plane* table = rule.on_table ? planes.table() : nullptr;
  const TableFootprint footprint(planes, rule.table_margin_m);
  const bool test_footprint = table != nullptr && footprint.valid();
  constexpr std::size_t kFootprintStep = 4;
  Eigen::Vector4f table_model = Eigen::Vector4f::Zero();
  if (table != nullptr) {
    const Eigen::Vector3f normal = table->normal.cast<float>();
    table_model = {normal.x(), normal.y(), normal.z(), static_cast<float>(table->offset_m)};
  }
  std::vector<std::int64_t> raised_px(count, 0);
  std::vector<std::int64_t> sampled_px(count, 0);
  std::vector<std::int64_t> outside_px(count, 0);
  auto* label = blobs.labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = blobs.labels.total();
  for (std::size_t i = 0; i < total; ++i) {
    const auto id = static_cast<std::size_t>(label[i]);
    if (id == 0) continue;
    ++size_px[id];
    const float* p = point + 3 * i;
    bool on_plane = false;
    for (std::size_t k = 0; k < plane_count; ++k) {
      const Eigen::Vector4f& m = models[k];
      const float d = m.x() * p[0] + m.y() * p[1] + m.z() * p[2] + m.w();
      if (d < -rule.behind_margin_m) ++behind[id * plane_count + k];
      // Within a horizontal support's band but clearly above it is the top of a flat object.
      const bool raised = horizontal_support[k] != 0 && d > rule.min_rise_m;
      on_plane = on_plane || (std::abs(d) <= rule.on_plane_distance_m && !raised);
    }
    on_plane_px[id] += on_plane ? 1 : 0;
    if (table != nullptr) {
      const float height = table_model.x() * p[0] + table_model.y() * p[1] +
                           table_model.z() * p[2] + table_model.w();
      raised_px[id] += height > rule.min_rise_m ? 1 : 0;
      if (test_footprint && i % kFootprintStep == 0) {
        ++sampled_px[id];
        outside_px[id] += footprint.contains(p) ? 0 : 1;
      }
    }
  }
  std::vector<char> keep(count, 0);
  for (std::size_t id = 1; id < count; ++id) {
    const auto size = static_cast<double>(size_px[id]);
    bool is_behind = false;
    for (std::size_t k = 0; k < plane_count && rule.drop_behind; ++k) {
      if (static_cast<double>(behind[id * plane_count + k]) > rule.max_behind_fraction * size) {
        is_behind = true;
      }
    }
    const bool is_on_plane =
        static_cast<double>(on_plane_px[id]) > rule.max_on_plane_fraction * size;
    const bool not_raised =
        table != nullptr && static_cast<double>(raised_px[id]) < rule.min_raised_fraction * size;
    const bool outside = test_footprint && sampled_px[id] > 0 &&
                         static_cast<double>(outside_px[id]) >
                             rule.max_outside_fraction * static_cast<double>(sampled_px[id]);
    if (is_behind) {
      ++dropped.behind;
    } else if (is_on_plane) {
      ++dropped.on_plane;
    } else if (not_raised) {
      ++dropped.not_raised;
    } else if (outside) {
      ++dropped.outside_table;
    } else {
      keep[id] = 1;
    }
  }
  keep_blobs(blobs, keep);
  return dropped;
}

std::int32_t keep_blobs(EuclideanRegions& blobs, const std::vector<char>& keep) {
  std::vector<std::int32_t> new_id(keep.size(), 0);
  std::int32_t kept = 0;
  for (std::size_t id = 1; id < keep.size(); ++id) {
    if (keep[id] != 0) new_id[id] = ++kept;
  }
  if (kept == blobs.count) return 0;  // ids unchanged: no pass over the image
  auto* label = blobs.labels.ptr<std::int32_t>();
  const std::size_t total = blobs.labels.total();
  for (std::size_t i = 0; i < total; ++i)
    label[i] = new_id[static_cast<std::size_t>(label[i])];
  const std::int32_t removed = blobs.count - kept;
  blobs.count = kept;
  return removed;
}

}  // namespace facet::blobs
