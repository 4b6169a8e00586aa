#include "blobs/edge_attachment.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace facet::blobs {
namespace {

// Marks the pixels of an edge-only region too small to keep, until the end of the pass.
constexpr std::int32_t kTooSmall = -1;

class EdgeGrid {
 public:
  EdgeGrid(cv::Mat& labels, const cv::Mat& edges, const cv::Mat& xyz,
           const algo::NeighbourGate& gate)
      : rows_(edges.rows),
        cols_(edges.cols),
        label_(labels.ptr<std::int32_t>()),
        edge_(edges.ptr<std::uint8_t>()),
        point_(xyz.ptr<float>()),
        gate_(gate) {}

  std::int32_t* label() { return label_; }
  bool is_edge(int i) const { return edge_[i] != 0; }
  bool linked(int a, int b) const {
    return gate_.close(point_ + 3 * static_cast<std::ptrdiff_t>(a),
                       point_ + 3 * static_cast<std::ptrdiff_t>(b));
  }
  // Calls visit(n) for each 8-neighbour n of pixel i, in raster order, until visit returns true.
  template <class Visit>
  void neighbours(int i, Visit visit) const {
    const int y = i / cols_;
    const int x = i % cols_;
    for (int dy = -1; dy <= 1; ++dy) {
      const int ny = y + dy;
      if (ny < 0 || ny >= rows_) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx;
        if ((dx == 0 && dy == 0) || nx < 0 || nx >= cols_) continue;
        if (visit(ny * cols_ + nx)) return;
      }
    }
  }
  // Spreads the labels of the pixels in `queue` breadth first to the free, linked edge pixels,
  // appending each pixel it labels to `queue`.
  void spread(std::vector<std::int32_t>& queue) {
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int i = queue[head];
      neighbours(i, [&](int n) {
        if (edge_[n] != 0 && label_[n] == 0 && linked(i, n)) {
          label_[n] = label_[i];
          queue.push_back(n);
        }
        return false;
      });
    }
  }

 private:
  int rows_;
  int cols_;
  std::int32_t* label_;
  const std::uint8_t* edge_;
  const float* point_;
  algo::NeighbourGate gate_;
};

// Ids back in raster order of each blob's first pixel (attached edge pixels may come before a
// blob's first patch pixel); a pass over the image only when the order changed.
void restore_raster_order(EuclideanRegions& blobs) {
  std::vector<std::int32_t> by_first(static_cast<std::size_t>(blobs.count));
  std::iota(by_first.begin(), by_first.end(), 1);
  std::sort(by_first.begin(), by_first.end(), [&](std::int32_t a, std::int32_t b) {
    return blobs.first_px[static_cast<std::size_t>(a)] <
           blobs.first_px[static_cast<std::size_t>(b)];
  });
  std::vector<std::int32_t> new_id(static_cast<std::size_t>(blobs.count) + 1, 0);
  bool same = true;
  for (std::size_t rank = 0; rank < by_first.size(); ++rank) {
    new_id[static_cast<std::size_t>(by_first[rank])] = static_cast<std::int32_t>(rank + 1);
    same = same && by_first[rank] == static_cast<std::int32_t>(rank + 1);
  }
  if (same) return;
  auto* label = blobs.labels.ptr<std::int32_t>();
  const std::size_t total = blobs.labels.total();
  for (std::size_t i = 0; i < total; ++i)
    label[i] = new_id[static_cast<std::size_t>(label[i])];
  std::vector<std::int64_t> first(blobs.first_px.size(), -1);
  for (std::size_t id = 1; id < first.size(); ++id)
    first[static_cast<std::size_t>(new_id[id])] = blobs.first_px[id];
  blobs.first_px = std::move(first);
}

// Whether the rule keeps the region (raster indices, its seed first) by its size and the depth
// of its seed, as grow_euclidean_regions judges a region by its first pixel.
bool keeps(const algo::RegionSizeRule& size, const std::vector<std::int32_t>& region,
           const cv::Mat& xyz) {
  const float* seed = xyz.ptr<float>() + 3 * static_cast<std::ptrdiff_t>(region.front());
  return size.keeps(static_cast<std::int64_t>(region.size()), static_cast<double>(seed[2]));
}

}  // namespace

EdgeAttachment attach_edge_pixels(EuclideanRegions& blobs, const cv::Mat& edges,
                                  std::span<const std::int32_t> edge_pixels, const cv::Mat& xyz,
                                  const algo::NeighbourGate& gate,
                                  const algo::RegionSizeRule* own_blob_size) {
  EdgeGrid grid(blobs.labels, edges, xyz, gate);
  std::int32_t* label = grid.label();
  EdgeAttachment result;
  bool reordered = false;
  const auto note_first = [&](std::int32_t id, int i) {
    std::int64_t& first = blobs.first_px[static_cast<std::size_t>(id)];
    if (i < first) {
      first = i;
      reordered = true;
    }
  };

  // Breadth first from the blobs: an edge pixel goes to the blob that reaches it in the fewest
  // steps. The first step is taken from the edge pixels' side: an edge pixel next to a blob
  // joins its first neighbour in raster order that is a patch pixel of a blob close enough.
  std::vector<std::int32_t> queue;
  for (const std::int32_t i : edge_pixels) {
    std::int32_t owner = 0;
    grid.neighbours(i, [&](int n) {
      if (label[n] > 0 && !grid.is_edge(n) && grid.linked(i, n)) owner = label[n];
      return owner != 0;
    });
    if (owner == 0) continue;
    label[i] = owner;
    queue.push_back(i);
  }
  grid.spread(queue);
  result.attached_px = static_cast<std::int64_t>(queue.size());
  for (const std::int32_t i : queue)
    note_first(label[i], i);

  // The edge pixels no blob reached: blobs of their own when large enough. In raster order, a
  // region's seed is its first pixel.
  std::vector<std::int32_t> region;
  std::vector<std::int32_t> too_small;
  for (const std::int32_t seed : edge_pixels) {
    if (own_blob_size == nullptr) break;
    if (label[seed] != 0) continue;
    region.assign(1, seed);
    label[seed] = blobs.count + 1;
    grid.spread(region);
    if (keeps(*own_blob_size, region, xyz)) {
      ++blobs.count;
      ++result.edge_only_blobs;
      blobs.first_px.push_back(seed);
      reordered = reordered || blobs.count > 1;
    } else {
      for (const std::int32_t i : region)
        label[i] = kTooSmall;
      too_small.insert(too_small.end(), region.begin(), region.end());
    }
  }
  for (const std::int32_t i : too_small)
    label[i] = 0;
  if (reordered) restore_raster_order(blobs);
  return result;
}

}  // namespace facet::blobs
