#include "facet/algo/label_pieces.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace facet::algo {

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

  // The marked pixels in raster order, and for each its place in that list (written only at
  // marked pixels and read only at pixels whose label is marked: no clearing per call). The
  // work after this one scan is proportional to the marked pixels, usually a small part of the
  // image (what a plane left of a patch).
  pixels_.clear();
  if (compact_.size() < static_cast<std::size_t>(total))
    compact_.resize(static_cast<std::size_t>(total));
  for (std::int32_t i = 0; i < total; ++i) {
    if (!marked(label[i])) continue;
    compact_[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(pixels_.size());
    pixels_.push_back(i);
  }
  if (pixels_.empty()) return count;

  // Union-find over the marked pixels; a root is always its piece's first pixel in raster order
  // (the smaller index wins), so the result does not depend on the order of the joins.
  const auto n = static_cast<std::int32_t>(pixels_.size());
  pieces_.reset(static_cast<std::size_t>(n));
  for (std::int32_t k = 0; k < n; ++k) {
    const std::int32_t i = pixels_[static_cast<std::size_t>(k)];
    if (!valid(i)) continue;
    const std::int32_t id = label[i];
    const int x = i % width;
    // The neighbours already visited: west, and north-west, north, north-east.
    const std::int32_t before[4] = {x > 0 ? i - 1 : -1, x > 0 ? i - width - 1 : -1, i - width,
                                    x + 1 < width ? i - width + 1 : -1};
    for (const std::int32_t j : before) {
      if (j < 0 || label[j] != id || !valid(j)) continue;
      if (!gate.close(xyz + 3 * i, xyz + 3 * j)) continue;
      pieces_.unite(k, compact_[static_cast<std::size_t>(j)]);
    }
  }

  size_px_.assign(static_cast<std::size_t>(n), 0);
  for (std::int32_t k = 0; k < n; ++k)
    ++size_px_[static_cast<std::size_t>(pieces_.flatten(k))];
  largest_.assign(split.size(), -1);
  for (std::int32_t k = 0; k < n; ++k) {
    if (!pieces_.is_root(k)) continue;  // roots only, in raster order
    std::int32_t& best =
        largest_[static_cast<std::size_t>(label[pixels_[static_cast<std::size_t>(k)]])];
    if (best < 0 ||
        size_px_[static_cast<std::size_t>(k)] > size_px_[static_cast<std::size_t>(best)])
      best = k;
  }
  // New ids go to the roots (size_px_ is reused for them); then every pixel takes its root's.
  std::int32_t next = count;
  for (std::int32_t k = 0; k < n; ++k) {
    if (!pieces_.is_root(k)) continue;
    const std::int32_t id = label[pixels_[static_cast<std::size_t>(k)]];
    size_px_[static_cast<std::size_t>(k)] =
        largest_[static_cast<std::size_t>(id)] == k ? id : ++next;
  }
  for (std::int32_t k = 0; k < n; ++k) {
    label[pixels_[static_cast<std::size_t>(k)]] =
        size_px_[static_cast<std::size_t>(pieces_.parent(k))];
  }
  return next;
}

}  // namespace facet::algo
