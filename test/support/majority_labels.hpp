#pragma once
// Which found object (label) holds most of each ground-truth object's pixels: the vote the
// tests of whole-frame runs judge merges and losses by.

#include <cstdint>
#include <map>
#include <opencv2/core.hpp>
#include <vector>

namespace facet::test {

// For each rendered object id 1..count: the found object (label) holding most of its pixels, 0
// when most of them carry none.
inline std::vector<int> majority_labels(const cv::Mat& object, int count, const cv::Mat& labels) {
  std::vector<std::map<int, std::int64_t>> votes(static_cast<std::size_t>(count) + 1);
  for (int v = 0; v < object.rows; ++v) {
    for (int u = 0; u < object.cols; ++u) {
      const int id = object.at<int>(v, u);
      if (id > 0 && id <= count)
        ++votes[static_cast<std::size_t>(id)][labels.at<std::uint16_t>(v, u)];
    }
  }
  std::vector<int> majority(static_cast<std::size_t>(count) + 1, 0);
  for (int id = 1; id <= count; ++id) {
    std::int64_t best = -1;
    for (const auto& [label, n] : votes[static_cast<std::size_t>(id)]) {
      if (n > best) {
        best = n;
        majority[static_cast<std::size_t>(id)] = label;
      }
    }
  }
  return majority;
}

}  // namespace facet::test
