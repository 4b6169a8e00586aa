#include "partition/object_labels.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "facet/algo/label_runs.hpp"

namespace facet::partition {
namespace {

// Breadth-first growth of the labels of the pixels in `queue` into unlabelled pixels of the
// same blob; first come, first served, so the result depends only on the queue's order.
void grow_within_blobs(cv::Mat& objects, const cv::Mat& blobs, std::vector<std::int32_t>& queue) {
  const int width = objects.cols;
  const int height = objects.rows;
  auto* labels = objects.ptr<std::int32_t>();
  const auto* blob = blobs.ptr<std::int32_t>();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t i = queue[head];
    const int u = i % width;
    const int v = i / width;
    for (int dv = -1; dv <= 1; ++dv) {
      for (int du = -1; du <= 1; ++du) {
        const int nu = u + du;
        const int nv = v + dv;
        if (nu < 0 || nv < 0 || nu >= width || nv >= height) continue;
        const std::int32_t j = nv * width + nu;
        if (labels[j] != 0 || blob[j] != blob[i]) continue;
        labels[j] = labels[i];
        queue.push_back(j);
      }
    }
  }
}

}  // namespace

void fill_blob_gaps(cv::Mat& objects, const cv::Mat& blobs_in, std::int32_t next_id) {
  const cv::Mat blobs = blobs_in.isContinuous() ? blobs_in : blobs_in.clone();
  auto* labels = objects.ptr<std::int32_t>();
  const auto* blob = blobs.ptr<std::int32_t>();
  const auto n = static_cast<std::int32_t>(objects.total());
  std::vector<std::int32_t> queue;
  bool any_gap = false;
  for (std::int32_t i = 0; i < n; ++i) {
    if (blob[i] <= 0) continue;
    if (labels[i] != 0) {
      queue.push_back(i);
    } else {
      any_gap = true;
    }
  }
  if (!any_gap) return;
  grow_within_blobs(objects, blobs, queue);
  for (std::int32_t i = 0; i < n; ++i) {
    if (blob[i] <= 0 || labels[i] != 0) continue;
    labels[i] = next_id++;
    queue.assign(1, i);
    grow_within_blobs(objects, blobs, queue);
  }
}

std::int32_t relabel_in_raster_order(cv::Mat& objects) {
  auto* labels = objects.ptr<std::int32_t>();
  const auto n = static_cast<std::int32_t>(objects.total());
  std::int32_t max_id = 0;
  for (std::int32_t i = 0; i < n; ++i)
    max_id = std::max(max_id, labels[i]);
  std::vector<std::int32_t> new_id(static_cast<std::size_t>(max_id) + 1, 0);
  std::int32_t count = 0;
  // By runs of one id along the raster: one lookup per run, not per pixel.
  algo::for_each_label_run(labels, static_cast<std::size_t>(n),
                           [&](std::int32_t id, std::size_t begin, std::size_t end) {
                             if (id <= 0) return;
                             std::int32_t& mapped = new_id[static_cast<std::size_t>(id)];
                             if (mapped == 0) mapped = ++count;
                             std::fill(labels + begin, labels + end, mapped);
                           });
  return count;
}

}  // namespace facet::partition
