#include "facet/algo/patch_contacts.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace facet::algo {
namespace {

// Contacts arrive in long runs of the same pair along a border; counting runs as they come
// keeps the list short before it is sorted.
class ContactCounter {
 public:
  void add(std::int32_t a, std::int32_t b) {
    const auto key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    if (!entries_.empty() && entries_.back().first == key) {
      ++entries_.back().second;
    } else {
      entries_.emplace_back(key, 1);
    }
  }

  void write_to(PatchAdjacency& adjacency) {
    std::sort(entries_.begin(), entries_.end());
    for (const auto& [pair, contacts] : entries_) {
      if (!adjacency.pairs.empty() && adjacency.pairs.back() == pair) {
        adjacency.contact_px.back() += contacts;
      } else {
        adjacency.pairs.push_back(pair);
        adjacency.contact_px.push_back(contacts);
      }
    }
  }

 private:
  std::vector<std::pair<std::pair<std::int32_t, std::int32_t>, std::int32_t>> entries_;
};

// True when the pixels [begin, end) of both rows carry one label: then no pixel in between
// touches another patch. Written as a reduction so that it vectorises.
bool one_label(const std::int32_t* here, const std::int32_t* below, int begin, int end) {
  const std::int32_t label = here[begin];
  std::uint32_t differs = 0;
  for (int x = begin; x < end; ++x)
    differs |= static_cast<std::uint32_t>(here[x] ^ label);
  if (below != nullptr) {
    for (int x = begin; x < end; ++x)
      differs |= static_cast<std::uint32_t>(below[x] ^ label);
  }
  return differs == 0;
}

void count_contacts(const std::int32_t* here, const std::int32_t* below, int begin, int end,
                    int width, ContactCounter& counter) {
  // Each unordered pixel pair once: look only E, SW, S and SE.
  for (int x = begin; x < end; ++x) {
    const std::int32_t a = here[x];
    if (a == 0) continue;
    if (x + 1 < width && here[x + 1] != a && here[x + 1] != 0) counter.add(a, here[x + 1]);
    if (below == nullptr) continue;
    for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
      const std::int32_t b = below[nx];
      if (b != a && b != 0) counter.add(a, b);
    }
  }
}

}  // namespace

PatchAdjacency find_patch_contacts(const LabelImage& patches) {
  const cv::Mat& labels = patches.labels;
  // Most of an image lies inside one patch (or outside all): blocks whose pixels and
  // neighbours share one label are skipped after a vectorised test.
  constexpr int kBlockPx = 32;
  ContactCounter counter;
  const int width = labels.cols;
  for (int row = 0; row < labels.rows; ++row) {
    const std::int32_t* here = labels.ptr<std::int32_t>(row);
    const std::int32_t* below = row + 1 < labels.rows ? labels.ptr<std::int32_t>(row + 1) : nullptr;
    for (int begin = 0; begin < width; begin += kBlockPx) {
      const int end = std::min(begin + kBlockPx, width);
      if (one_label(here, below, std::max(begin - 1, 0), std::min(end + 1, width))) continue;
      count_contacts(here, below, begin, end, width, counter);
    }
  }
  auto adjacency = of_frame<PatchAdjacency>(patches);
  adjacency.count = patches.count;
  counter.write_to(adjacency);
  return adjacency;
}

}  // namespace facet::algo
