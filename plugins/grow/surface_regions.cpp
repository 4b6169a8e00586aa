#include "grow/surface_regions.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "grow/pixel_classes.hpp"

namespace facet::grow {
namespace {

struct Run {
  int row;
  int begin;  // first column
  int end;    // one past the last column
};

// One bit per pixel of a row, set for surface pixels (bit x % 64 of word x / 64).
void surface_bits(const unsigned char* classes, int width, std::vector<std::uint64_t>& bits) {
  bits.assign(static_cast<std::size_t>(width) / 64 + 1, 0);
  int x = 0;
  // 8 pixels at a time: classes are 0, 1 or 2 and bit 1 marks kSurfacePixel. The multiplication
  // gathers bit 0 of byte i into bit 56 + i (the partial products never overlap).
  for (; x + 8 <= width; x += 8) {
    std::uint64_t word = 0;
    std::memcpy(&word, classes + x, sizeof(word));
    const std::uint64_t flags = (word >> 1) & 0x0101010101010101ULL;
    const std::uint64_t byte = (flags * 0x0102040810204080ULL) >> 56;
    bits[static_cast<std::size_t>(x / 64)] |= byte << (x % 64);
  }
  for (; x < width; ++x) {
    if (classes[x] == kSurfacePixel) bits[static_cast<std::size_t>(x / 64)] |= 1ULL << (x % 64);
  }
}

// The first column at or after `from` whose bit equals `value`, or `width`.
int next_column(const std::vector<std::uint64_t>& bits, int from, bool value, int width) {
  while (from < width) {
    const std::uint64_t word = bits[static_cast<std::size_t>(from / 64)];
    const std::uint64_t wanted = (value ? word : ~word) >> (from % 64);
    if (wanted != 0) return std::min(from + __builtin_ctzll(wanted), width);
    from = (from / 64 + 1) * 64;
  }
  return width;
}

// Runs of surface pixels found with bit scans: a row of 640 pixels is 10 words.
std::vector<Run> find_runs(const cv::Mat& classes, std::vector<std::size_t>& row_first) {
  std::vector<Run> runs;
  std::vector<std::uint64_t> bits;
  row_first.assign(static_cast<std::size_t>(classes.rows) + 1, 0);
  const int width = classes.cols;
  for (int row = 0; row < classes.rows; ++row) {
    row_first[static_cast<std::size_t>(row)] = runs.size();
    surface_bits(classes.ptr<unsigned char>(row), width, bits);
    int x = next_column(bits, 0, true, width);
    while (x < width) {
      const int end = next_column(bits, x, false, width);
      runs.push_back({row, x, end});
      x = next_column(bits, end, true, width);
    }
  }
  row_first.back() = runs.size();
  return runs;
}

// Union-find over run indices. The root of a set is always its smallest index, i.e. the set's
// first run in raster order, which gives raster-ordered region ids for free.
class RunSets {
 public:
  explicit RunSets(std::size_t count) : parent_(count) {
    for (std::size_t i = 0; i < count; ++i)
      parent_[i] = i;
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];  // path halving
      i = parent_[i];
    }
    return i;
  }
  // Points every run straight at its root in one forward pass: a parent always has a smaller
  // index, so it already points at the root when its children are visited.
  void flatten() {
    for (std::size_t i = 0; i < parent_.size(); ++i)
      parent_[i] = parent_[parent_[i]];
  }
  // After flatten().
  std::size_t root(std::size_t i) const { return parent_[i]; }
  void join(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a < b) {
      parent_[b] = a;
    } else if (b < a) {
      parent_[a] = b;
    }
  }

 private:
  std::vector<std::size_t> parent_;
};

// Joins each run with the runs of the previous row it touches. With 8-connectivity, runs that
// only meet diagonally (one ends where the other begins, one column apart) touch too.
void join_touching_runs(const std::vector<Run>& runs, const std::vector<std::size_t>& row_first,
                        int connectivity, RunSets& sets) {
  const int slack = connectivity == 8 ? 1 : 0;
  for (std::size_t row = 1; row + 1 < row_first.size(); ++row) {
    std::size_t above = row_first[row - 1];
    const std::size_t above_end = row_first[row];
    for (std::size_t i = row_first[row]; i < row_first[row + 1]; ++i) {
      const Run& run = runs[i];
      while (above < above_end && runs[above].end + slack <= run.begin)
        ++above;
      for (std::size_t j = above; j < above_end && runs[j].begin < run.end + slack; ++j) {
        sets.join(i, j);
      }
    }
  }
}

}  // namespace

SurfaceRegions label_surface_regions(const cv::Mat& classes, int connectivity,
                                     std::int64_t min_size_px) {
  if (classes.type() != CV_8UC1) throw std::invalid_argument("pixel classes must be CV_8UC1");
  if (connectivity != 4 && connectivity != 8) {
    throw std::invalid_argument("connectivity must be 4 or 8");
  }
  std::vector<std::size_t> row_first;
  const std::vector<Run> runs = find_runs(classes, row_first);
  RunSets sets(runs.size());
  join_touching_runs(runs, row_first, connectivity, sets);
  sets.flatten();

  std::vector<std::int64_t> size_px(runs.size(), 0);
  for (std::size_t i = 0; i < runs.size(); ++i)
    size_px[sets.root(i)] += runs[i].end - runs[i].begin;

  // Roots come in raster order of their first pixel; number the large enough ones.
  SurfaceRegions result;
  std::vector<std::int32_t> id(runs.size(), 0);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (sets.root(i) == i && size_px[i] >= min_size_px) id[i] = ++result.count;
  }
  result.labels = cv::Mat::zeros(classes.size(), CV_32SC1);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::int32_t label = id[sets.root(i)];
    if (label == 0) continue;
    const Run run = runs[i];  // a copy: stores to the labels cannot alias it
    std::fill(result.labels.ptr<std::int32_t>(run.row) + run.begin,
              result.labels.ptr<std::int32_t>(run.row) + run.end, label);
    result.labelled_px += run.end - run.begin;
  }
  return result;
}

}  // namespace facet::grow
