#include "eval/frame_stability.hpp"

#include <cmath>
#include <map>

namespace facet::eval {
namespace {

struct Centroids {
  std::vector<cv::Point2d> pixel;
  std::vector<cv::Vec3d> metric;
  std::vector<std::int64_t> valid_points;  // points that entered the metric centroid
};

// Centroids of the segments listed in `ids` (ascending), in pixels and, with points, in metres
// over the segment's valid points.
Centroids centroids_of(const cv::Mat& labels, const cv::Mat& points,
                       const std::vector<std::int32_t>& ids) {
  std::map<std::int32_t, std::size_t> index;
  for (std::size_t i = 0; i < ids.size(); ++i)
    index[ids[i]] = i;
  Centroids sums{std::vector<cv::Point2d>(ids.size()), std::vector<cv::Vec3d>(ids.size()),
                 std::vector<std::int64_t>(ids.size(), 0)};
  std::vector<std::int64_t> pixels(ids.size(), 0);
  for (int y = 0; y < labels.rows; ++y) {
    const auto* row = labels.ptr<std::int32_t>(y);
    const auto* point_row = points.empty() ? nullptr : points.ptr<cv::Vec3f>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (row[x] == 0) continue;
      const std::size_t i = index.at(row[x]);
      sums.pixel[i] += cv::Point2d(x, y);
      ++pixels[i];
      if (point_row == nullptr) continue;
      const cv::Vec3f& p = point_row[x];
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) {
        sums.metric[i] += cv::Vec3d(p[0], p[1], p[2]);
        ++sums.valid_points[i];
      }
    }
  }
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (pixels[i] > 0) sums.pixel[i] *= 1.0 / static_cast<double>(pixels[i]);
    if (sums.valid_points[i] > 0) sums.metric[i] *= 1.0 / static_cast<double>(sums.valid_points[i]);
  }
  return sums;
}

}  // namespace

FrameStability compare_frames(const cv::Mat& labels_before, const cv::Mat& points_before,
                              const cv::Mat& labels_after, const cv::Mat& points_after,
                              const StabilityOptions& options) {
  const OverlapTable table = count_overlap(labels_before, labels_after);
  const std::vector<SegmentPair> pairs =
      match_segments(table, options.measure, options.min_overlap);
  const Centroids before = centroids_of(labels_before, points_before, table.ids_a);
  const Centroids after = centroids_of(labels_after, points_after, table.ids_b);

  FrameStability result;
  result.segments = static_cast<std::int64_t>(table.ids_b.size());
  result.spurious = result.segments - static_cast<std::int64_t>(pairs.size());
  result.vanished = static_cast<std::int64_t>(table.ids_a.size() - pairs.size());
  const bool metric = !points_before.empty() && !points_after.empty();
  for (const SegmentPair& pair : pairs) {
    result.overlaps.push_back(pair.overlap);
    result.centroid_px.push_back(cv::norm(after.pixel[pair.b] - before.pixel[pair.a]));
    if (metric && before.valid_points[pair.a] > 0 && after.valid_points[pair.b] > 0) {
      result.centroid_mm.push_back(1000.0 * cv::norm(after.metric[pair.b] - before.metric[pair.a]));
    }
  }
  return result;
}

}  // namespace facet::eval
