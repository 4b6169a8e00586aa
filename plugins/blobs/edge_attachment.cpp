#include "blobs/edge_attachment.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace facet::blobs {
namespace {

bool close(const float* a, const float* b, float max_squared_m2) {
  const float dx = a[0] - b[0];
  const float dy = a[1] - b[1];
  const float dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz < max_squared_m2;
}

// Ids in raster order of each region's first pixel, as grow_euclidean_regions gives them.
std::int32_t renumber_in_raster_order(cv::Mat& labels, std::int32_t count) {
  std::vector<std::int32_t> new_id(static_cast<std::size_t>(count) + 1, 0);
  std::int32_t next = 0;
  auto* label = labels.ptr<std::int32_t>();
  const std::size_t total = labels.total();
  for (std::size_t i = 0; i < total; ++i) {
    const std::int32_t id = label[i];
    if (id == 0) continue;
    std::int32_t& mapped = new_id[static_cast<std::size_t>(id)];
    if (mapped == 0) mapped = ++next;
    label[i] = mapped;
  }
  return next;
}

}  // namespace

EdgeAttachment attach_edge_pixels(EuclideanRegions& blobs, const cv::Mat& edges, const cv::Mat& xyz,
                                  float max_distance_m, std::int64_t min_size_px) {
  const int rows = edges.rows;
  const int cols = edges.cols;
  const float max_squared = max_distance_m * max_distance_m;
  auto* label = blobs.labels.ptr<std::int32_t>();
  const auto* edge = edges.ptr<std::uint8_t>();
  const auto* point = xyz.ptr<float>();
  EdgeAttachment result;

  // Breadth first from the blobs: an edge pixel goes to the blob that reaches it in the fewest
  // steps. The first step is taken from the edge pixels' side, which are few, rather than from
  // every blob pixel: an edge pixel next to a blob joins its first neighbour in raster order
  // that is a blob pixel close enough; the steps after it spread from those pixels in turn.
  std::vector<std::int32_t> queue;
  const auto free_edge = [&](int y, int x) {
    const std::size_t i =
        static_cast<std::size_t>(y) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(x);
    return edge[i] != 0 && label[i] == 0;
  };
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      const int i = y * cols + x;
      if (edge[i] == 0 || label[i] != 0) continue;
      std::int32_t owner = 0;
      for (int dy = -1; dy <= 1 && owner == 0; ++dy) {
        for (int dx = -1; dx <= 1 && owner == 0; ++dx) {
          const int ny = y + dy;
          const int nx = x + dx;
          if (ny < 0 || ny >= rows || nx < 0 || nx >= cols) continue;
          const int n = ny * cols + nx;
          // Only blob pixels that were blobs before this pass (not edge pixels claimed in it).
          if (label[n] == 0 || edge[n] != 0) continue;
          if (close(point + 3 * static_cast<std::ptrdiff_t>(i),
                    point + 3 * static_cast<std::ptrdiff_t>(n), max_squared))
            owner = label[n];
        }
      }
      if (owner == 0) continue;
      label[i] = owner;
      ++result.attached_px;
      queue.push_back(i);
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    const int y = i / cols;
    const int x = i % cols;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int ny = y + dy;
        const int nx = x + dx;
        if (ny < 0 || ny >= rows || nx < 0 || nx >= cols || !free_edge(ny, nx)) continue;
        const int n = ny * cols + nx;
        if (!close(point + 3 * static_cast<std::ptrdiff_t>(i),
                   point + 3 * static_cast<std::ptrdiff_t>(n), max_squared))
          continue;
        label[n] = label[i];
        ++result.attached_px;
        queue.push_back(n);
      }
    }
  }

  // The edge pixels no blob reached: blobs of their own when large enough.
  cv::Mat leftover(edges.size(), CV_8UC1);
  auto* left = leftover.ptr<std::uint8_t>();
  const std::size_t total = edges.total();
  bool any = false;
  for (std::size_t i = 0; min_size_px >= 0 && i < total; ++i) {
    left[i] = edge[i] != 0 && label[i] == 0 ? 1 : 0;
    any = any || left[i] != 0;
  }
  if (any) {
    const EuclideanRegions extra =
        grow_euclidean_regions(leftover, xyz, max_distance_m, min_size_px);
    if (extra.count > 0) {
      const auto* extra_label = extra.labels.ptr<std::int32_t>();
      for (std::size_t i = 0; i < total; ++i) {
        if (extra_label[i] != 0) label[i] = blobs.count + extra_label[i];
      }
      result.edge_only_blobs = extra.count;
      blobs.count += extra.count;
    }
  }
  if (result.attached_px > 0 || result.edge_only_blobs > 0) {
    blobs.count = renumber_in_raster_order(blobs.labels, blobs.count);
  }
  return result;
}

}  // namespace facet::blobs
