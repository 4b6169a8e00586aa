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

void collect_blob_gaps(const cv::Mat& objects, const cv::Mat& blobs,
                       std::vector<std::int32_t>& gaps) {
  const auto* labels = objects.ptr<std::int32_t>();
  const auto* blob = blobs.ptr<std::int32_t>();
  const auto n = static_cast<std::int32_t>(objects.total());
  gaps.clear();
  // Gaps are few, so blocks without one are passed after a test that vectorises.
  constexpr std::int32_t kBlockPx = 64;
  for (std::int32_t begin = 0; begin < n; begin += kBlockPx) {
    const std::int32_t end = std::min(begin + kBlockPx, n);
    std::uint32_t any = 0;
    for (std::int32_t i = begin; i < end; ++i)
      any |= static_cast<std::uint32_t>(blob[i] > 0) & static_cast<std::uint32_t>(labels[i] == 0);
    if (any == 0) continue;
    for (std::int32_t i = begin; i < end; ++i) {
      if (blob[i] > 0 && labels[i] == 0) gaps.push_back(i);
    }
  }
}

void fill_blob_gaps(cv::Mat& objects, const cv::Mat& blobs_in, std::int32_t next_id) {
  const cv::Mat blobs = blobs_in.isContinuous() ? blobs_in : blobs_in.clone();
  std::vector<std::int32_t> gaps;
  collect_blob_gaps(objects, blobs, gaps);
  fill_blob_gaps(objects, blobs, next_id, gaps);
}

void fill_blob_gaps(cv::Mat& objects, const cv::Mat& blobs, std::int32_t next_id,
                    std::span<const std::int32_t> gaps) {
  if (gaps.empty()) return;
  auto* labels = objects.ptr<std::int32_t>();
  const auto* blob = blobs.ptr<std::int32_t>();
  const int width = objects.cols;
  const int height = objects.rows;

  // The growth starts from the labelled pixels next to a gap, in raster order. A labelled pixel
  // with no gap among its 8 neighbours would label nothing when its turn came (labels are only
  // ever added), so leaving it out changes nothing but the time: most labelled pixels are such.
  std::vector<std::int32_t> queue;
  for (const std::int32_t gap : gaps) {
    const int u = gap % width;
    const int v = gap / width;
    for (int nv = std::max(v - 1, 0); nv <= std::min(v + 1, height - 1); ++nv) {
      for (int nu = std::max(u - 1, 0); nu <= std::min(u + 1, width - 1); ++nu) {
        const std::int32_t j = nv * width + nu;
        if (blob[j] > 0 && labels[j] != 0) queue.push_back(j);
      }
    }
  }
  std::sort(queue.begin(), queue.end());
  queue.erase(std::unique(queue.begin(), queue.end()), queue.end());
  grow_within_blobs(objects, blobs, queue);

  // What no labelled pixel reached: each connected part becomes an object, in raster order.
  for (const std::int32_t i : gaps) {
    if (labels[i] != 0) continue;
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
