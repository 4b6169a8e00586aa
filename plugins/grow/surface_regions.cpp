#include "grow/surface_regions.hpp"

#include <cstddef>
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

std::vector<Run> find_runs(const cv::Mat& classes, std::vector<std::size_t>& row_first) {
  std::vector<Run> runs;
  row_first.assign(static_cast<std::size_t>(classes.rows) + 1, 0);
  for (int row = 0; row < classes.rows; ++row) {
    row_first[static_cast<std::size_t>(row)] = runs.size();
    const unsigned char* in = classes.ptr<unsigned char>(row);
    int x = 0;
    while (x < classes.cols) {
      while (x < classes.cols && in[x] != kSurfacePixel)
        ++x;
      if (x == classes.cols) break;
      const int begin = x;
      while (x < classes.cols && in[x] == kSurfacePixel)
        ++x;
      runs.push_back({row, begin, x});
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

  std::vector<std::int64_t> size_px(runs.size(), 0);
  for (std::size_t i = 0; i < runs.size(); ++i)
    size_px[sets.find(i)] += runs[i].end - runs[i].begin;

  // Roots come in raster order of their first pixel; number the large enough ones.
  SurfaceRegions result;
  std::vector<std::int32_t> id(runs.size(), 0);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (sets.find(i) == i && size_px[i] >= min_size_px) id[i] = ++result.count;
  }
  result.labels = cv::Mat::zeros(classes.size(), CV_32SC1);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::int32_t label = id[sets.find(i)];
    if (label == 0) continue;
    std::int32_t* out = result.labels.ptr<std::int32_t>(runs[i].row);
    for (int x = runs[i].begin; x < runs[i].end; ++x)
      out[x] = label;
    result.labelled_px += runs[i].end - runs[i].begin;
  }
  return result;
}

}  // namespace facet::grow
