#include "planes/flat_objects.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "facet/algo/label_runs.hpp"

namespace facet::planes {
namespace {

// The search runs on cells of 2 x 2 pixels, each sampled at one pixel: a quarter of the pixels
// to read, filter, label and shape. Lengths of the rule, given in pixels, are halved (rounded
// up). The pixels of a region found are given back at full resolution.
constexpr int kCellPx = 2;

int to_cells(double length_px) {
  return std::max(1, static_cast<int>(std::ceil(length_px / kCellPx)));
}

// Median of the cell heights under `mask` (cells with a table pixel only); NaN when none.
float median_height(const cv::Mat& mask, const cv::Mat& height_m, const cv::Mat& table_px,
                    std::vector<float>& values) {
  values.clear();
  for (int v = 0; v < mask.rows; ++v) {
    const auto* m = mask.ptr<std::uint8_t>(v);
    const auto* h = height_m.ptr<float>(v);
    const auto* n = table_px.ptr<float>(v);
    for (int u = 0; u < mask.cols; ++u) {
      if (m[u] != 0 && n[u] > 0.0F) values.push_back(h[u]);
    }
  }
  if (values.empty()) return std::numeric_limits<float>::quiet_NaN();
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Per cell: the height above the table of its first pixel (top left) when that is a table pixel
// (cell_px 1), else 0 (cell_px 0). One pixel in four is enough for a mean over a window, and the
// pass over the points is the rule's largest cost. With rule.max_height_m, a pixel on no plane
// whose point lies within that height of the table counts too when it is in a low piece: a piece
// of a patch a plane cut (`cut_pieces`) with low_patch_fraction of its sampled points that low (a
// stripe the table's plane cut off the table's patch). An object's own patch never counts (its
// region would take a ring of table), nor an edge pixel (one beside a bowl made a low region of
// its own on a real frame). `cell_patch` keeps the low pieces' ids, for the give-back. (Testing
// for a cut piece before the height, to skip the objects' pixels, took more instructions.)
void sample_cells(const cv::Mat& plane_labels, std::int32_t table_label, const cv::Mat& left_labels,
                  std::int32_t patch_count, const std::vector<char>& cut_pieces, const cv::Mat& xyz,
                  const algo::Plane& table, const FlatObjectRule& rule, cv::Mat& height_m,
                  cv::Mat& cell_px, cv::Mat& cell_patch, std::vector<std::int64_t>& patch_px,
                  std::vector<std::int64_t>& low_px, std::vector<char>& low_patch) {
  const cv::Size cells((xyz.cols + kCellPx - 1) / kCellPx, (xyz.rows + kCellPx - 1) / kCellPx);
  height_m.create(cells, CV_32FC1);
  cell_px.create(cells, CV_32FC1);
  cell_patch.create(cells, CV_32SC1);
  const bool low_points = rule.max_height_m > 0.0F;
  patch_px.assign(static_cast<std::size_t>(patch_count) + 1, 0);
  low_px.assign(static_cast<std::size_t>(patch_count) + 1, 0);
  for (int cv_row = 0; cv_row < cells.height; ++cv_row) {
    const auto* plane = plane_labels.ptr<std::int32_t>(cv_row * kCellPx);
    const auto* left = left_labels.ptr<std::int32_t>(cv_row * kCellPx);
    const auto* point = xyz.ptr<float>(cv_row * kCellPx);
    auto* height = height_m.ptr<float>(cv_row);
    auto* count = cell_px.ptr<float>(cv_row);
    auto* patch = cell_patch.ptr<std::int32_t>(cv_row);
    for (int cu = 0; cu < cells.width; ++cu) {
      const int u = cu * kCellPx;
      const bool on_table = plane[u] == table_label;
      const bool off_planes = low_points && plane[u] == 0 && !std::isnan(point[3 * u + 2]);
      const float h = on_table || off_planes ? table.signed_distance_m(point + 3 * u) : 0.0F;
      const bool low = off_planes && std::abs(h) <= rule.max_height_m;
      if (off_planes) {
        const auto id = static_cast<std::size_t>(left[u]);
        ++patch_px[id];
        low_px[id] += low ? 1 : 0;
      }
      height[cu] = on_table || low ? h : 0.0F;
      count[cu] = on_table ? 1.0F : 0.0F;
      patch[cu] = low ? left[u] : -1;
    }
  }
  low_patch.assign(patch_px.size(), 0);
  if (!low_points) return;
  // The low candidates count where their piece is low throughout; edge pixels (id 0) never.
  for (std::size_t id = 1; id < patch_px.size(); ++id) {
    low_patch[id] = id < cut_pieces.size() && cut_pieces[id] != 0 && patch_px[id] > 0 &&
                    static_cast<double>(low_px[id]) >=
                        rule.low_patch_fraction * static_cast<double>(patch_px[id]);
  }
  for (int cv_row = 0; cv_row < cells.height; ++cv_row) {
    auto* height = height_m.ptr<float>(cv_row);
    auto* count = cell_px.ptr<float>(cv_row);
    auto* patch = cell_patch.ptr<std::int32_t>(cv_row);
    for (int cu = 0; cu < cells.width; ++cu) {
      if (patch[cu] < 0) continue;
      if (low_patch[static_cast<std::size_t>(patch[cu])] != 0) {
        count[cu] = 1.0F;
      } else {
        height[cu] = 0.0F;
        patch[cu] = -1;
      }
    }
  }
}

// Row `row` of the raised mask: a table cell whose window (side `window`, centred, clipped to the
// grid) has a mean height above `min_height_m`. `height_sums` and `count_sums` are the
// summed-area tables (CV_64FC1, one row and one column larger than the grid) of the cells'
// heights and of their table pixels. The columns whose window is not clipped run without
// branches, so that the compiler vectorises them.
void raised_row(const cv::Mat& height_sums, const cv::Mat& count_sums, const cv::Mat& cell_px,
                int row, int window, double min_height_m, std::uint8_t* raised) {
  const int half = window / 2;
  const int top_row = std::max(0, row - half);
  const int bottom_row = std::min(height_sums.rows - 1, row - half + window);
  const double* h_top = height_sums.ptr<double>(top_row);
  const double* h_bottom = height_sums.ptr<double>(bottom_row);
  const double* n_top = count_sums.ptr<double>(top_row);
  const double* n_bottom = count_sums.ptr<double>(bottom_row);
  const float* count = cell_px.ptr<float>(row);
  const int cols = cell_px.cols;
  const int last = height_sums.cols - 1;
  const auto cell = [&](int u, int left, int right) {
    const double height = h_bottom[right] - h_top[right] - h_bottom[left] + h_top[left];
    const double pixels = n_bottom[right] - n_top[right] - n_bottom[left] + n_top[left];
    return static_cast<std::uint8_t>((count[u] > 0.0F) & (height > min_height_m * pixels) ? 255
                                                                                          : 0);
  };
  const int first_inner = std::min(cols, half);
  const int end_inner = std::max(first_inner, std::min(cols, last - window + half + 1));
  for (int u = 0; u < first_inner; ++u)
    raised[u] = cell(u, std::max(0, u - half), std::min(last, u - half + window));
  for (int u = first_inner; u < end_inner; ++u)
    raised[u] = cell(u, u - half, u - half + window);
  for (int u = end_inner; u < cols; ++u)
    raised[u] = cell(u, std::max(0, u - half), std::min(last, u - half + window));
}

// The low patches that lie mostly (half or more of their pixels) inside a region found join its
// patch: the stripes of the flat object's top that the table's plane cut off.
void join_low_patches(cv::Mat& left_labels, FlatObjectBuffers& b) {
  if (std::none_of(b.inside_px.begin(), b.inside_px.end(), [](std::int64_t n) { return n > 0; }))
    return;
  std::vector<std::int64_t>& size_px = b.patch_px;  // recounted at full resolution
  std::fill(size_px.begin(), size_px.end(), 0);
  auto* left = left_labels.ptr<std::int32_t>();
  const std::size_t total = left_labels.total();
  algo::for_each_label_run(left, total, [&](std::int32_t id, std::size_t begin, std::size_t end) {
    const auto slot = static_cast<std::size_t>(id);
    if (slot < size_px.size()) size_px[slot] += static_cast<std::int64_t>(end - begin);
  });
  algo::for_each_label_run(left, total, [&](std::int32_t id, std::size_t begin, std::size_t end) {
    const auto slot = static_cast<std::size_t>(id);
    if (slot == 0 || slot >= size_px.size() || 2 * b.inside_px[slot] < size_px[slot]) return;
    std::fill(left + begin, left + end, b.region_id[slot]);
  });
}

}  // namespace

std::int32_t give_flat_objects_back(cv::Mat& plane_labels, std::int32_t table_label,
                                    cv::Mat& left_labels, std::int32_t patch_count,
                                    const std::vector<char>& cut_pieces, const cv::Mat& xyz,
                                    const algo::Plane& table, const FlatObjectRule& rule,
                                    FlatObjectBuffers& buffers, std::int64_t& moved_px) {
  moved_px = 0;
  if (rule.window_px <= 0 || table_label <= 0 || xyz.empty()) return patch_count;
  FlatObjectBuffers& b = buffers;
  sample_cells(plane_labels, table_label, left_labels, patch_count, cut_pieces, xyz, table, rule,
               b.height_m, b.table_px, b.cell_patch, b.patch_px, b.low_px, b.low_patch);

  // Mean height of the table cells in each window (windows reach over holes and objects), from
  // summed-area tables of the heights and of the table pixels.
  const int window = to_cells(rule.window_px);
  cv::integral(b.height_m, b.height_sums, CV_64F);
  cv::integral(b.table_px, b.count_sums, CV_64F);
  b.raised.create(b.table_px.size(), CV_8UC1);
  for (int v = 0; v < b.raised.rows; ++v) {
    raised_row(b.height_sums, b.count_sums, b.table_px, v, window,
               static_cast<double>(rule.min_height_m), b.raised.ptr<std::uint8_t>(v));
  }
  // Fewer raised cells than one region needs: nothing to label (most frames of a bare table).
  const std::int64_t raised_px = std::int64_t{kCellPx * kCellPx} * cv::countNonZero(b.raised);
  if (raised_px < rule.min_px) return patch_count;
  cv::Mat stats;
  cv::Mat centroids;
  const int regions =
      cv::connectedComponentsWithStats(b.raised, b.components, stats, centroids, 8, CV_32S);

  // The shape and border tests look at the region's box, grown by the outer ring's reach.
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
  const int margin_cells = to_cells(2.0);  // the smoothing blurs a region's border this far
  const int reach_cells = to_cells(6.0);   // the outer ring's far side
  const cv::Rect grid(0, 0, b.components.cols, b.components.rows);
  std::vector<float> values;
  std::int32_t count = patch_count;
  b.inside_px.assign(b.low_patch.size(), 0);
  b.region_id.assign(b.low_patch.size(), 0);
  for (int r = 1; r < regions; ++r) {
    // Every cell of a region holds a table pixel of the sample: kCellPx^2 pixels each.
    const std::int64_t region_px =
        std::int64_t{kCellPx * kCellPx} * stats.at<std::int32_t>(r, cv::CC_STAT_AREA);
    if (region_px < rule.min_px) continue;
    const cv::Rect box = cv::Rect(stats.at<std::int32_t>(r, cv::CC_STAT_LEFT) - reach_cells,
                                  stats.at<std::int32_t>(r, cv::CC_STAT_TOP) - reach_cells,
                                  stats.at<std::int32_t>(r, cv::CC_STAT_WIDTH) + 2 * reach_cells,
                                  stats.at<std::int32_t>(r, cv::CC_STAT_HEIGHT) + 2 * reach_cells) &
                         grid;
    cv::compare(b.components(box), r, b.region, cv::CMP_EQ);
    // Its width, with the holes that the pixels of no plane leave closed: a strip along the
    // foot of an object (the band of its side within delta of the table, smoothed with the
    // table around it) is a few pixels wide, a flat object many.
    cv::morphologyEx(b.region, b.closed, cv::MORPH_CLOSE, kernel, cv::Point(-1, -1), margin_cells);
    cv::distanceTransform(b.closed, b.distance, cv::DIST_L2, 3);
    double widest_half_cells = 0.0;
    cv::minMaxLoc(b.distance, nullptr, &widest_half_cells);
    if (2.0 * kCellPx * widest_half_cells < rule.min_width_px) continue;
    // The border test: the heights just inside the region against those of the table just
    // outside it, both bands kept clear of the blurred border.
    cv::erode(b.region, b.inner, kernel, cv::Point(-1, -1), margin_cells);
    cv::dilate(b.region, b.outer_far, kernel, cv::Point(-1, -1), reach_cells);
    cv::dilate(b.region, b.outer_near, kernel, cv::Point(-1, -1), margin_cells);
    b.outer_far.setTo(0, b.outer_near);
    const float inside = median_height(b.inner, b.height_m(box), b.table_px(box), values);
    const float outside = median_height(b.outer_far, b.height_m(box), b.table_px(box), values);
    if (!(inside - outside >= rule.min_step_m)) continue;  // NaN: no band to compare

    ++count;
    const int row_end = std::min(xyz.rows, (box.y + box.height) * kCellPx);
    const int col_end = std::min(xyz.cols, (box.x + box.width) * kCellPx);
    for (int v = box.y * kCellPx; v < row_end; ++v) {
      const auto* in_region = b.region.ptr<std::uint8_t>(v / kCellPx - box.y);
      const auto* point = xyz.ptr<float>(v);
      auto* plane = plane_labels.ptr<std::int32_t>(v);
      auto* left = left_labels.ptr<std::int32_t>(v);
      for (int u = box.x * kCellPx; u < col_end; ++u) {
        if (in_region[u / kCellPx - box.x] == 0) continue;
        if (plane[u] == table_label) {
          plane[u] = 0;
          left[u] = count;
          ++moved_px;
          continue;
        }
        const auto id = static_cast<std::size_t>(left[u]);
        if (plane[u] != 0 || id >= b.low_patch.size() || (id != 0 && b.low_patch[id] == 0))
          continue;
        if (id != 0) {
          // A low patch joins the region it lies in mostly; counted here, joined below.
          ++b.inside_px[id];
          b.region_id[id] = count;
        } else if (std::abs(table.signed_distance_m(point + 3 * u)) <= rule.max_height_m) {
          left[u] = count;  // an edge pixel of the object's top (NaN fails the test)
        }
      }
    }
  }
  join_low_patches(left_labels, b);
  return count;
}

}  // namespace facet::planes
