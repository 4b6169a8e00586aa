#include "partition/blob_segments.hpp"

#include <algorithm>
#include <cmath>

#include "facet/error.hpp"
#include "facet/image_checks.hpp"

namespace facet::partition {

void check_partition_inputs(const cv::Mat& blobs, const cv::Mat& patches, const cv::Mat& points) {
  require_same_size(blobs, "blobs", patches, "patches");
  require_same_size(blobs, "blobs", points, "points");
}

void BlobSegments::build(const cv::Mat& blob_labels, const cv::Mat& patch_labels,
                         const cv::Mat& point_image) {
  x.clear();
  y.clear();
  z.clear();
  pixel.clear();
  segments.clear();
  blobs.clear();
  by_patch_.clear();
  max_patch = 0;
  const int width = blob_labels.cols;

  // Pass 1: the pixels that take part, and the largest ids.
  std::int32_t max_blob = 0;
  for (int v = 0; v < blob_labels.rows; ++v) {
    const auto* blob_row = blob_labels.ptr<std::int32_t>(v);
    const auto* patch_row = patch_labels.ptr<std::int32_t>(v);
    const auto* point_row = point_image.ptr<cv::Vec3f>(v);
    for (int u = 0; u < width; ++u) {
      if (blob_row[u] <= 0) continue;
      const cv::Vec3f& p = point_row[u];
      if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) continue;
      by_patch_.push_back(v * width + u);
      max_blob = std::max(max_blob, blob_row[u]);
      max_patch = std::max(max_patch, patch_row[u]);
    }
  }
  const auto n = static_cast<std::int32_t>(by_patch_.size());
  if (n == 0) return;
  const auto* blob_data = blob_labels.isContinuous() ? blob_labels.ptr<std::int32_t>() : nullptr;
  const auto* patch_data = patch_labels.isContinuous() ? patch_labels.ptr<std::int32_t>() : nullptr;
  auto blob_at = [&](std::int32_t i) {
    return blob_data ? blob_data[i] : blob_labels.at<std::int32_t>(i / width, i % width);
  };
  auto patch_at = [&](std::int32_t i) {
    const std::int32_t id =
        patch_data ? patch_data[i] : patch_labels.at<std::int32_t>(i / width, i % width);
    return std::max(id, 0);
  };

  // Two stable counting sorts (patch, then blob) give blob-major, patch-minor, raster order in
  // O(pixels + ids), where a comparison sort of a VGA frame's object pixels would dominate the
  // stage's run time.
  std::vector<std::int32_t>& order = pixel;
  order.resize(static_cast<std::size_t>(n));
  counts_.assign(static_cast<std::size_t>(max_patch) + 2, 0);
  for (const std::int32_t i : by_patch_)
    ++counts_[static_cast<std::size_t>(patch_at(i)) + 1];
  for (std::size_t k = 1; k < counts_.size(); ++k)
    counts_[k] += counts_[k - 1];
  for (const std::int32_t i : by_patch_) {
    order[static_cast<std::size_t>(counts_[static_cast<std::size_t>(patch_at(i))]++)] = i;
  }
  counts_.assign(static_cast<std::size_t>(max_blob) + 2, 0);
  for (const std::int32_t i : order)
    ++counts_[static_cast<std::size_t>(blob_at(i)) + 1];
  for (std::size_t k = 1; k < counts_.size(); ++k)
    counts_[k] += counts_[k - 1];
  for (const std::int32_t i : order) {
    by_patch_[static_cast<std::size_t>(counts_[static_cast<std::size_t>(blob_at(i))]++)] = i;
  }
  pixel.swap(by_patch_);

  x.resize(static_cast<std::size_t>(n));
  y.resize(static_cast<std::size_t>(n));
  z.resize(static_cast<std::size_t>(n));
  for (std::int32_t k = 0; k < n; ++k) {
    const std::int32_t i = pixel[static_cast<std::size_t>(k)];
    const cv::Vec3f& p = point_image.at<cv::Vec3f>(i / width, i % width);
    x[static_cast<std::size_t>(k)] = p[0];
    y[static_cast<std::size_t>(k)] = p[1];
    z[static_cast<std::size_t>(k)] = p[2];
  }

  // Runs of equal (blob, patch) are the segments; runs of equal blob the blob ranges.
  std::int32_t k = 0;
  while (k < n) {
    const std::int32_t blob = blob_at(pixel[static_cast<std::size_t>(k)]);
    BlobRange range{blob, static_cast<std::int32_t>(segments.size()), 0, k, 0};
    while (k < n && blob_at(pixel[static_cast<std::size_t>(k)]) == blob) {
      const std::int32_t patch = patch_at(pixel[static_cast<std::size_t>(k)]);
      Segment segment{patch, k, k};
      while (k < n && blob_at(pixel[static_cast<std::size_t>(k)]) == blob &&
             patch_at(pixel[static_cast<std::size_t>(k)]) == patch) {
        ++k;
      }
      segment.end = k;
      segments.push_back(segment);
    }
    range.segment_end = static_cast<std::int32_t>(segments.size());
    range.end = k;
    blobs.push_back(range);
  }
}

}  // namespace facet::partition
