#pragma once
// The valid 3D points of every blob, gathered into flat arrays and grouped by blob, then by surface
// patch, then in raster order. Both partition stages work on contiguous index ranges of these
// arrays, so a plane is tested against a patch with one tight, vectorisable loop.

#include <algorithm>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace facet::partition {

// The points of one blob that lie in one patch (patch 0: in no patch), [begin, end) in the arrays.
struct Segment {
  std::int32_t patch = 0;
  std::int32_t begin = 0;
  std::int32_t end = 0;
  std::int32_t size() const { return end - begin; }
};

// The step through a segment's raster-ordered points that takes at most `max_samples` of them,
// spread over the whole patch rather than its first rows.
inline std::int32_t sample_stride(const Segment& segment, std::int32_t max_samples) {
  return std::max<std::int32_t>(
      1, (segment.size() + max_samples - 1) / std::max<std::int32_t>(max_samples, 1));
}

// One non-empty blob: its segments [segment_begin, segment_end), ascending patch id, and its
// points [begin, end).
struct BlobRange {
  std::int32_t blob = 0;
  std::int32_t segment_begin = 0;
  std::int32_t segment_end = 0;
  std::int32_t begin = 0;
  std::int32_t end = 0;
};

// Throws StageError unless blobs, patches and points are of one size (their types are their
// packets' promise).
void check_partition_inputs(const cv::Mat& blobs, const cv::Mat& patches, const cv::Mat& points);

class BlobSegments {
 public:
  // Gathers every pixel with a blob id > 0 and a finite point. Label counts are taken from the
  // images themselves, so a stale `count` field cannot cause an out-of-range access. The buffers
  // are kept from frame to frame.
  void build(const cv::Mat& blob_labels, const cv::Mat& patch_labels, const cv::Mat& point_image);

  // Point coordinates (metres) and flat pixel index, structure of arrays.
  std::vector<float> x;
  std::vector<float> y;
  std::vector<float> z;
  std::vector<std::int32_t> pixel;
  std::vector<Segment> segments;
  std::vector<BlobRange> blobs;
  std::int32_t max_patch = 0;  // largest patch id seen in a blob

 private:
  std::vector<std::int32_t> by_patch_;  // pixel indices after the first counting pass
  std::vector<std::int32_t> counts_;
};

}  // namespace facet::partition
