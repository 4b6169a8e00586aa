#include "eval/segment_matching.hpp"

#include <algorithm>
#include <map>

#include "eval/assignment.hpp"

namespace facet::eval {
namespace {

// Ids in ascending order with their pixel counts.
void collect_ids(const cv::Mat& labels, std::vector<std::int32_t>& ids,
                 std::vector<std::int64_t>& pixels) {
  std::map<std::int32_t, std::int64_t> counts;
  for (int y = 0; y < labels.rows; ++y) {
    const auto* row = labels.ptr<std::int32_t>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (row[x] != 0) ++counts[row[x]];
    }
  }
  for (const auto& [id, count] : counts) {
    ids.push_back(id);
    pixels.push_back(count);
  }
}

std::size_t index_of(const std::vector<std::int32_t>& ids, std::int32_t id) {
  return static_cast<std::size_t>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
}

}  // namespace

double overlap_of(OverlapMeasure measure, std::int64_t both, std::int64_t pixels_a,
                  std::int64_t pixels_b) {
  if (both <= 0 || pixels_a <= 0 || pixels_b <= 0) return 0.0;
  const auto shared = static_cast<double>(both);
  if (measure == OverlapMeasure::iou) {
    return shared / static_cast<double>(pixels_a + pixels_b - both);
  }
  return 0.5 * (shared / static_cast<double>(pixels_a) + shared / static_cast<double>(pixels_b));
}

OverlapTable count_overlap(const cv::Mat& labels_a, const cv::Mat& labels_b) {
  CV_Assert(labels_a.type() == CV_32SC1 && labels_b.type() == CV_32SC1);
  CV_Assert(labels_a.size() == labels_b.size());
  OverlapTable table;
  collect_ids(labels_a, table.ids_a, table.pixels_a);
  collect_ids(labels_b, table.ids_b, table.pixels_b);
  table.both.assign(table.ids_a.size() * table.ids_b.size(), 0);
  for (int y = 0; y < labels_a.rows; ++y) {
    const auto* row_a = labels_a.ptr<std::int32_t>(y);
    const auto* row_b = labels_b.ptr<std::int32_t>(y);
    for (int x = 0; x < labels_a.cols; ++x) {
      if (row_a[x] == 0 || row_b[x] == 0) continue;
      ++table.both[index_of(table.ids_a, row_a[x]) * table.ids_b.size() +
                   index_of(table.ids_b, row_b[x])];
    }
  }
  return table;
}

std::vector<SegmentPair> match_segments(const OverlapTable& table, OverlapMeasure measure,
                                        double min_overlap) {
  const std::size_t n = table.ids_a.size();
  const std::size_t m = table.ids_b.size();
  WeightMatrix weights(n, m);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < m; ++b) {
      weights.at(a, b) =
          overlap_of(measure, table.shared(a, b), table.pixels_a[a], table.pixels_b[b]);
    }
  }
  std::vector<SegmentPair> pairs;
  const auto assigned = max_weight_assignment(weights);
  for (std::size_t a = 0; a < n; ++a) {
    if (!assigned[a]) continue;
    const double overlap = weights.at(a, *assigned[a]);
    if (table.shared(a, *assigned[a]) > 0 && overlap > min_overlap) {
      pairs.push_back({a, *assigned[a], overlap});
    }
  }
  return pairs;
}

}  // namespace facet::eval
