#include "blobs/euclidean_regions.hpp"

#include <cstddef>
#include <cstring>
#include <vector>

#include "facet/algo/disjoint_sets.hpp"

namespace facet::blobs {

EuclideanRegions grow_euclidean_regions(const cv::Mat& mask, const cv::Mat& xyz,
                                        const algo::NeighbourGate& gate,
                                        const algo::RegionSizeRule& size) {
  const int rows = mask.rows;
  const int cols = mask.cols;
  const std::size_t total = mask.total();
  const auto* point = xyz.ptr<float>();
  // Pixel sets whose root is the set's first pixel in raster order: ids in raster order need no
  // sorting. Only mask pixels are made.
  algo::DisjointSets sets;
  sets.reset_unmade(total);

  // Raster scan: each pixel is linked to its already visited 8-neighbours (W, NW, N, NE).
  for (int row = 0; row < rows; ++row) {
    const unsigned char* in = mask.ptr<unsigned char>(row);
    const unsigned char* above = row > 0 ? mask.ptr<unsigned char>(row - 1) : nullptr;
    for (int col = 0; col < cols; ++col) {
      if (in[col] == 0) {
        // Most of the image is table, walls or invalid: skip 8 pixels at a time.
        std::uint64_t word = 0;
        while (col + 8 <= cols && (std::memcpy(&word, in + col, sizeof(word)), word == 0))
          col += 8;
        if (col >= cols || in[col] == 0) continue;
      }
      const std::size_t i = static_cast<std::size_t>(row) * cols + col;
      const auto pixel = static_cast<std::int32_t>(i);
      sets.make(pixel);
      const float* p = point + 3 * i;
      if (col > 0 && in[col - 1] != 0 && gate.close(p, p - 3)) sets.unite(pixel, pixel - 1);
      if (above == nullptr) continue;
      const std::size_t up = i - static_cast<std::size_t>(cols);
      for (int dc = -1; dc <= 1; ++dc) {
        const int c = col + dc;
        if (c < 0 || c >= cols || above[c] == 0) continue;
        const std::size_t j = up + static_cast<std::size_t>(c - col);
        if (gate.close(p, point + 3 * j)) sets.unite(pixel, static_cast<std::int32_t>(j));
      }
    }
  }

  // A parent always has a smaller index than its child, so one forward pass points every pixel
  // at its root (the parent is already flat when the child is visited) and sizes the sets; a
  // root is visited before the rest of its set, which is when its count starts.
  const auto* in = mask.ptr<unsigned char>();
  std::vector<std::int32_t> size_px(total);  // valid at roots only
  for (std::size_t i = 0; i < total; ++i) {
    if (in[i] == 0) continue;
    const auto root = static_cast<std::size_t>(sets.flatten(static_cast<std::int32_t>(i)));
    if (root == i) size_px[i] = 0;
    ++size_px[root];
  }
  // A set under min_px is judged at the depth of its first pixel (the root): it spans a few
  // centimetres at most, and a mean would cost a sum over every pixel of every set.
  const auto kept = [&](std::size_t root) {
    return size.keeps(size_px[root], static_cast<double>(point[3 * root + 2]));
  };
  // Ids for the roots of large enough sets, in raster order; every pixel is written once.
  EuclideanRegions out;
  out.labels.create(rows, cols, CV_32SC1);
  out.first_px.push_back(-1);
  auto* label = out.labels.ptr<std::int32_t>();
  std::vector<std::int32_t>& id_of_root = size_px;  // reused: a root's size becomes its id
  for (std::size_t i = 0; i < total; ++i) {
    if (in[i] == 0) {
      label[i] = 0;
      continue;
    }
    const auto root = static_cast<std::size_t>(sets.parent(static_cast<std::int32_t>(i)));
    if (root == i) {
      id_of_root[i] = kept(i) ? ++out.count : 0;
      if (id_of_root[i] != 0) out.first_px.push_back(static_cast<std::int64_t>(i));
    }
    label[i] = id_of_root[root];
  }
  return out;
}

}  // namespace facet::blobs
