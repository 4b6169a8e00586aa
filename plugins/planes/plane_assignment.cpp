#include "planes/plane_assignment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "facet/algo/label_runs.hpp"

namespace facet::planes {
namespace {

// What one pass over the points tells of each patch: its valid points, those clearly off the
// planes (beyond 2 delta from all), the summed height above the table of its points within delta
// of the table (and of no larger plane before it), and per (patch, plane) the points within
// delta and their squared distances.
struct PatchStatistics {
  std::vector<std::int64_t> off_px;
  std::vector<double> table_height_sum_m;
  std::vector<double> near_squared_m2;
};

// Which patches give their points within delta to which planes: all but object faces.
struct JoinRule {
  std::vector<char> joins_any;         // per slot: gives its points to the walls
  std::vector<char> joins_horizontal;  // per slot: gives its points to the table and floor
  std::vector<char> horizontal;        // per plane: a table or floor

  bool joins(std::size_t slot, std::size_t plane) const {
    return horizontal[plane] != 0 ? joins_horizontal[slot] != 0 : joins_any[slot] != 0;
  }
};

}  // namespace

PlaneAssignment assign_to_planes(const cv::Mat& patch_labels, std::int32_t patch_count,
                                 const cv::Mat& xyz, const std::vector<algo::Plane>& planes,
                                 const std::vector<PlaneRole>& roles, int table,
                                 const AssignmentRule& rule, cv::Mat& plane_labels,
                                 cv::Mat& left_labels) {
  plane_labels.create(patch_labels.size(), CV_32SC1);
  left_labels.create(patch_labels.size(), CV_32SC1);
  auto* plane_of = plane_labels.ptr<std::int32_t>();
  auto* left = left_labels.ptr<std::int32_t>();
  const auto* label = patch_labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = patch_labels.total();
  const float delta_m = rule.inlier_distance_m;

  const auto patch_slots = static_cast<std::size_t>(std::max(0, patch_count)) + 1;
  // Slot 0 collects pixels of no patch (or of an id outside 1..count).
  const auto patch_slot = [&](std::int32_t id) {
    return id > 0 && id <= patch_count ? static_cast<std::size_t>(id) : std::size_t{0};
  };
  const std::size_t plane_count = planes.size();
  const std::size_t table_c = table >= 0 ? static_cast<std::size_t>(table) : plane_count;

  PlaneAssignment out;
  out.patch_px.assign(patch_slots, 0);
  out.near_px.assign(patch_slots * plane_count, 0);
  PatchStatistics stats;
  stats.off_px.assign(patch_slots, 0);
  stats.table_height_sum_m.assign(patch_slots, 0.0);
  stats.near_squared_m2.assign(patch_slots * plane_count, 0.0);
  // By runs of one patch label: the patch's counters stay in registers along the run. The sums
  // are still taken point by point in raster order, so they come out exactly as per pixel.
  algo::for_each_label_run(label, total, [&](std::int32_t id, std::size_t begin, std::size_t end) {
    const std::size_t slot = patch_slot(id);
    std::int64_t* near_px = out.near_px.data() + slot * plane_count;
    double* near_squared_m2 = stats.near_squared_m2.data() + slot * plane_count;
    double table_height_sum_m = stats.table_height_sum_m[slot];
    std::int64_t valid_px = 0;
    std::int64_t off_px = 0;
    for (std::size_t i = begin; i < end; ++i) {
      const float* p = point + 3 * i;
      std::int32_t near = 0;
      if (std::isfinite(p[2])) {
        ++valid_px;
        bool off = true;
        for (std::size_t c = 0; c < plane_count; ++c) {
          const float d = planes[c].signed_distance_m(p);
          const float distance = std::abs(d);
          off = off && distance > 2.0F * delta_m;
          if (distance <= delta_m) {
            near = static_cast<std::int32_t>(c + 1);
            ++near_px[c];
            near_squared_m2[c] += static_cast<double>(d) * d;
            if (c == table_c) table_height_sum_m += d;
            break;
          }
        }
        off_px += off ? 1 : 0;
      }
      plane_of[i] = near;
    }
    out.valid_px += valid_px;
    out.patch_px[slot] += valid_px;
    stats.off_px[slot] += off_px;
    stats.table_height_sum_m[slot] = table_height_sum_m;
  });

  // The object faces: a face that lies mostly well off the planes keeps its points from every
  // plane; a raised one (the table's points lie around 0 above it, a book's top at
  // min_object_height_m and more, a flat object's bottom band spread over 0..delta) from the
  // table's level and the floor.
  JoinRule join;
  join.joins_any.assign(patch_slots, 1);
  join.joins_horizontal.assign(patch_slots, 1);
  for (std::size_t slot = 1; slot < patch_slots; ++slot) {
    const auto size = static_cast<double>(out.patch_px[slot]);
    join.joins_any[slot] =
        static_cast<double>(stats.off_px[slot]) < rule.object_face_off_plane_fraction * size;
    const std::int64_t table_near_px =
        table_c < plane_count ? out.near_px[slot * plane_count + table_c] : 0;
    const bool raised =
        table_near_px > 0 &&
        stats.table_height_sum_m[slot] > 0.5 * static_cast<double>(rule.min_object_height_m) *
                                             static_cast<double>(table_near_px);
    join.joins_horizontal[slot] = join.joins_any[slot] != 0 && !raised ? 1 : 0;
  }
  join.horizontal.assign(plane_count, 0);
  for (std::size_t c = 0; c < plane_count; ++c)
    join.horizontal[c] = roles[c] != PlaneRole::wall ? 1 : 0;

  // The planes' inliers and RMS, of the points that join them.
  out.inliers.assign(plane_count, 0);
  std::vector<double> squared_sum(plane_count, 0.0);
  for (std::size_t slot = 0; slot < patch_slots; ++slot) {
    for (std::size_t c = 0; c < plane_count; ++c) {
      if (!join.joins(slot, c)) continue;
      out.inliers[c] += out.near_px[slot * plane_count + c];
      squared_sum[c] += stats.near_squared_m2[slot * plane_count + c];
    }
  }
  out.rms_m.assign(plane_count, 0.0);
  for (std::size_t c = 0; c < plane_count; ++c) {
    out.rms_m[c] =
        out.inliers[c] > 0 ? std::sqrt(squared_sum[c] / static_cast<double>(out.inliers[c])) : 0.0;
  }

  // Which pixels join their plane, per slot and plane id (id 0, no plane, never joins); again by
  // runs of one patch label.
  const std::size_t stride = plane_count + 1;
  std::vector<std::uint8_t> joins(patch_slots * stride, 0);
  for (std::size_t slot = 0; slot < patch_slots; ++slot) {
    for (std::size_t c = 0; c < plane_count; ++c)
      joins[slot * stride + c + 1] = join.joins(slot, c) ? 1 : 0;
  }
  out.left_px.assign(patch_slots, 0);
  algo::for_each_label_run(label, total, [&](std::int32_t id, std::size_t begin, std::size_t end) {
    const std::size_t slot = patch_slot(id);
    const std::uint8_t* joins_slot = joins.data() + slot * stride;
    std::int64_t joined_px = 0;
    for (std::size_t i = begin; i < end; ++i) {
      const std::int32_t near = plane_of[i];
      const bool joined = joins_slot[near] != 0;
      plane_of[i] = joined ? near : 0;
      left[i] = joined ? 0 : static_cast<std::int32_t>(slot);
      joined_px += joined ? 1 : 0;
    }
    out.plane_px += joined_px;
    out.left_px[slot] += static_cast<std::int64_t>(end - begin) - joined_px;
  });
  return out;
}

}  // namespace facet::planes
