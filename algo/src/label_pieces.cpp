#include "facet/algo/label_pieces.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace facet::algo {

std::int32_t LabelPieces::find(std::int32_t i) {
  while (parent_[static_cast<std::size_t>(i)] != i) {
    const auto up = static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)]);
    parent_[static_cast<std::size_t>(i)] = parent_[up];  // path halving
    i = parent_[static_cast<std::size_t>(i)];
  }
  return i;
}

std::int32_t LabelPieces::split(cv::Mat& labels, std::int32_t count, const std::vector<char>& split,
                                const cv::Mat& points, const NeighbourGate& gate) {
  if (labels.type() != CV_32SC1 || points.type() != CV_32FC3 || labels.size() != points.size() ||
      !labels.isContinuous() || !points.isContinuous()) {
    throw std::invalid_argument(
        "LabelPieces::split needs continuous CV_32SC1 labels and CV_32FC3 points of one size");
  }
  const int width = labels.cols;
  const auto total = static_cast<std::int32_t>(labels.total());
  auto* label = labels.ptr<std::int32_t>();
  const float* xyz = points.ptr<float>();
  const auto marked = [&](std::int32_t id) {
    return id > 0 && static_cast<std::size_t>(id) < split.size() &&
           split[static_cast<std::size_t>(id)] != 0;
  };
  const auto valid = [&](std::int32_t i) { return std::isfinite(xyz[3 * i + 2]); };

  // Union-find over the marked pixels; a root is always the piece's first pixel in raster order
  // (the smaller index wins), so the result does not depend on the order of the joins.
  parent_.assign(static_cast<std::size_t>(total), -1);
  bool any = false;
  for (std::int32_t i = 0; i < total; ++i) {
    const std::int32_t id = label[i];
    if (!marked(id)) continue;
    any = true;
    parent_[static_cast<std::size_t>(i)] = i;
    if (!valid(i)) continue;
    const int x = i % width;
    // The neighbours already visited: west, and north-west, north, north-east.
    const std::int32_t before[4] = {x > 0 ? i - 1 : -1, x > 0 ? i - width - 1 : -1, i - width,
                                    x + 1 < width ? i - width + 1 : -1};
    for (const std::int32_t j : before) {
      if (j < 0 || label[j] != id || !valid(j)) continue;
      if (!gate.close(xyz + 3 * i, xyz + 3 * j)) continue;
      std::int32_t a = find(i);
      std::int32_t b = find(j);
      if (a == b) continue;
      if (a < b) std::swap(a, b);
      parent_[static_cast<std::size_t>(a)] = b;
    }
  }
  if (!any) return count;

  size_px_.assign(static_cast<std::size_t>(total), 0);
  for (std::int32_t i = 0; i < total; ++i) {
    if (parent_[static_cast<std::size_t>(i)] >= 0) ++size_px_[static_cast<std::size_t>(find(i))];
  }
  largest_.assign(split.size(), -1);
  for (std::int32_t i = 0; i < total; ++i) {
    if (parent_[static_cast<std::size_t>(i)] != i) continue;  // roots only, in raster order
    std::int32_t& best = largest_[static_cast<std::size_t>(label[i])];
    if (best < 0 ||
        size_px_[static_cast<std::size_t>(i)] > size_px_[static_cast<std::size_t>(best)])
      best = i;
  }
  new_id_.assign(static_cast<std::size_t>(total), 0);
  std::int32_t next = count;
  for (std::int32_t i = 0; i < total; ++i) {
    if (parent_[static_cast<std::size_t>(i)] != i) continue;
    new_id_[static_cast<std::size_t>(i)] =
        largest_[static_cast<std::size_t>(label[i])] == i ? label[i] : ++next;
  }
  for (std::int32_t i = 0; i < total; ++i) {
    if (parent_[static_cast<std::size_t>(i)] >= 0)
      label[i] = new_id_[static_cast<std::size_t>(find(i))];
  }
  return next;
}

}  // namespace facet::algo
