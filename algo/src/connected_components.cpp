#include "facet/algo/connected_components.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

namespace facet::algo {
namespace {

// One bit per pixel of a row, set where the pixel equals `value` (bit x % 64 of word x / 64).
void value_bits(const unsigned char* row, int width, std::uint8_t value,
                std::vector<std::uint64_t>& bits) {
  bits.assign(static_cast<std::size_t>(width) / 64 + 1, 0);
  constexpr std::uint64_t kLow7 = 0x7F7F7F7F7F7F7F7FULL;
  const std::uint64_t pattern = 0x0101010101010101ULL * value;
  int x = 0;
  // 8 pixels at a time. A byte of `diff` is 0 exactly where the pixel equals the value; its top
  // bit in `equal` is then set (the sum carries into the top bit for any non-zero low 7 bits,
  // and never across bytes). The multiplication gathers bit 0 of byte i into bit 56 + i (the
  // partial products never overlap).
  for (; x + 8 <= width; x += 8) {
    std::uint64_t word = 0;
    std::memcpy(&word, row + x, sizeof(word));
    const std::uint64_t diff = word ^ pattern;
    const std::uint64_t equal = ~(((diff & kLow7) + kLow7) | diff | kLow7);
    const std::uint64_t flags = equal >> 7;
    const std::uint64_t byte = (flags * 0x0102040810204080ULL) >> 56;
    bits[static_cast<std::size_t>(x / 64)] |= byte << (x % 64);
  }
  for (; x < width; ++x) {
    if (row[x] == value) bits[static_cast<std::size_t>(x / 64)] |= 1ULL << (x % 64);
  }
}

// The first column at or after `from` whose bit equals `set`, or `width`.
int next_column(const std::vector<std::uint64_t>& bits, int from, bool set, int width) {
  while (from < width) {
    const std::uint64_t word = bits[static_cast<std::size_t>(from / 64)];
    const std::uint64_t wanted = (set ? word : ~word) >> (from % 64);
    if (wanted != 0) return std::min(from + __builtin_ctzll(wanted), width);
    from = (from / 64 + 1) * 64;
  }
  return width;
}

}  // namespace

// Runs found with bit scans: a row of 640 pixels is 10 words.
void ComponentLabeler::find_runs(const cv::Mat& image, std::uint8_t value) {
  runs_.clear();
  row_first_.assign(static_cast<std::size_t>(image.rows) + 1, 0);
  const int width = image.cols;
  for (int row = 0; row < image.rows; ++row) {
    row_first_[static_cast<std::size_t>(row)] = runs_.size();
    value_bits(image.ptr<unsigned char>(row), width, value, bits_);
    int x = next_column(bits_, 0, true, width);
    while (x < width) {
      const int end = next_column(bits_, x, false, width);
      runs_.push_back({x, end});
      x = next_column(bits_, end, true, width);
    }
  }
  row_first_.back() = runs_.size();
}

// Joins each run with the runs of the previous row it touches. With 8-connectivity, runs that
// only meet diagonally (one ends where the other begins, one column apart) touch too.
void ComponentLabeler::join_touching_runs(int connectivity) {
  const int slack = connectivity == 8 ? 1 : 0;
  for (std::size_t row = 1; row + 1 < row_first_.size(); ++row) {
    std::size_t above = row_first_[row - 1];
    const std::size_t above_end = row_first_[row];
    for (std::size_t i = row_first_[row]; i < row_first_[row + 1]; ++i) {
      const Run run = runs_[i];
      while (above < above_end && runs_[above].end + slack <= run.begin)
        ++above;
      for (std::size_t j = above; j < above_end && runs_[j].begin < run.end + slack; ++j) {
        runs_joined_.unite(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
      }
    }
  }
}

// Writes every pixel once, row by row: the gaps between runs as 0, each run as its component's
// id (0 for a component under the minimum size), so the image needs no separate clearing pass.
void ComponentLabeler::write_labels(cv::Mat& labels) const {
  for (int row = 0; row < labels.rows; ++row) {
    std::int32_t* out = labels.ptr<std::int32_t>(row);
    int column = 0;
    for (std::size_t i = row_first_[static_cast<std::size_t>(row)];
         i < row_first_[static_cast<std::size_t>(row) + 1]; ++i) {
      const Run run = runs_[i];
      std::fill(out + column, out + run.begin, 0);
      std::fill(out + run.begin, out + run.end, id_of_run(i));
      column = run.end;
    }
    std::fill(out + column, out + labels.cols, 0);
  }
}

Components ComponentLabeler::label(const cv::Mat& image, std::uint8_t value, int connectivity,
                                   std::int64_t min_size_px, cv::Mat& labels) {
  if (image.type() != CV_8UC1) throw std::invalid_argument("components: the image must be CV_8UC1");
  if (labels.type() != CV_32SC1 || labels.size() != image.size()) {
    throw std::invalid_argument("components: labels must be CV_32SC1 of the image's size");
  }
  if (connectivity != 4 && connectivity != 8) {
    throw std::invalid_argument("components: connectivity must be 4 or 8");
  }
  find_runs(image, value);
  if (runs_.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw std::invalid_argument("components: image too large");
  }
  const std::size_t run_count = runs_.size();
  runs_joined_.reset(run_count);
  join_touching_runs(connectivity);
  // Every run straight at its root, in one ascending pass, and the sets' sizes.
  size_px_.assign(run_count, 0);
  for (std::size_t i = 0; i < run_count; ++i) {
    const auto root = static_cast<std::size_t>(runs_joined_.flatten(static_cast<std::int32_t>(i)));
    size_px_[root] += runs_[i].end - runs_[i].begin;
  }
  // Roots come in raster order of their first pixel; number the large enough ones.
  Components result;
  id_.assign(run_count, 0);
  size_of_id_.assign(1, 0);
  for (std::size_t i = 0; i < run_count; ++i) {
    if (runs_joined_.is_root(static_cast<std::int32_t>(i)) && size_px_[i] >= min_size_px) {
      id_[i] = ++result.count;
      size_of_id_.push_back(size_px_[i]);
      result.labelled_px += size_px_[i];
    }
  }
  write_labels(labels);
  return result;
}

void ComponentLabeler::relabel(const std::vector<std::int32_t>& new_id, cv::Mat& labels) {
  if (new_id.size() != size_of_id_.size()) {
    throw std::invalid_argument("components: relabel needs one new id per component");
  }
  if (labels.type() != CV_32SC1 || labels.rows + 1 != static_cast<int>(row_first_.size())) {
    throw std::invalid_argument("components: labels must be the ones label() wrote");
  }
  std::vector<std::int64_t> size_of_new_id(1, 0);
  for (std::size_t id = 1; id < new_id.size(); ++id) {
    if (new_id[id] == 0) continue;
    if (new_id[id] != static_cast<std::int32_t>(size_of_new_id.size())) {
      throw std::invalid_argument("components: new ids must be 1..n in order, without gaps");
    }
    size_of_new_id.push_back(size_of_id_[id]);
  }
  // The pixels first, while the runs still answer with the old ids (a dropped one's too).
  for_each_run([&](std::int32_t id, int row, int begin, int end) {
    std::int32_t* out = labels.ptr<std::int32_t>(row);
    std::fill(out + begin, out + end, new_id[static_cast<std::size_t>(id)]);
  });
  for (std::int32_t& id : id_)
    id = id == 0 ? 0 : new_id[static_cast<std::size_t>(id)];
  size_of_id_ = std::move(size_of_new_id);
}

}  // namespace facet::algo
