#include "grow/surface_regions.hpp"

#include <algorithm>
#include <stdexcept>

#include "grow/pixel_classes.hpp"

namespace facet::grow {

SurfaceRegions SurfaceRegionLabeler::label(const cv::Mat& classes, const cv::Mat& points,
                                           int connectivity, const algo::RegionSizeRule& size) {
  if (classes.type() != CV_8UC1) throw std::invalid_argument("pixel classes must be CV_8UC1");
  if (connectivity != 4 && connectivity != 8) {
    throw std::invalid_argument("connectivity must be 4 or 8");
  }
  SurfaceRegions result;
  // The image lives inside a buffer with zero guard rows above and below (a whole row and
  // kLabelGuardPx more pixels, even in narrow images), so that the assignment pass can load the
  // labels around any pixel as whole vectors. A full-width row range is still a continuous image.
  const int width = classes.cols;
  const int guard_rows = 1 + (kLabelGuardPx + width - 1) / std::max(width, 1);
  cv::Mat buffer(classes.rows + 2 * guard_rows, width, CV_32SC1);
  buffer.rowRange(0, guard_rows).setTo(0);
  buffer.rowRange(guard_rows + classes.rows, buffer.rows).setTo(0);
  result.labels = buffer.rowRange(guard_rows, guard_rows + classes.rows);
  const algo::Components regions =
      components_.label(classes, kSurfacePixel, connectivity, size.smallest_px(), result.labels);
  result.count = regions.count;
  result.labelled_px = regions.labelled_px;
  if (size.depends_on_depth()) drop_small_near_regions(points, size, result);
  return result;
}

void SurfaceRegionLabeler::drop_small_near_regions(const cv::Mat& points,
                                                   const algo::RegionSizeRule& size,
                                                   SurfaceRegions& regions) {
  if (points.type() != CV_32FC3 || points.size() != regions.labels.size()) {
    throw std::invalid_argument("points must be CV_32FC3 of the classes' size");
  }
  const auto count = static_cast<std::size_t>(regions.count);
  bool any_small = false;
  for (std::int32_t id = 1; id <= regions.count; ++id)
    any_small = any_small || components_.size_px(id) < size.min_px;
  if (!any_small) return;

  // Depth sums of the small regions only; the large ones are kept whatever their depth. Both
  // passes go over the labeler's runs, not over the image.
  depth_sum_m_.assign(count + 1, 0.0);
  components_.for_each_run([&](std::int32_t id, int row, int begin, int end) {
    if (components_.size_px(id) >= size.min_px) return;
    const auto* point = points.ptr<cv::Vec3f>(row);
    double& sum = depth_sum_m_[static_cast<std::size_t>(id)];
    for (int x = begin; x < end; ++x)
      sum += point[x][2];
  });
  new_id_.assign(count + 1, 0);
  std::int32_t kept = 0;
  for (std::int32_t id = 1; id <= regions.count; ++id) {
    const std::int64_t size_px = components_.size_px(id);
    const double mean_depth_m =
        depth_sum_m_[static_cast<std::size_t>(id)] / static_cast<double>(size_px);
    if (size.keeps(size_px, mean_depth_m)) {
      new_id_[static_cast<std::size_t>(id)] = ++kept;
    } else {
      regions.labelled_px -= size_px;
    }
  }
  if (kept == regions.count) return;
  components_.relabel(new_id_, regions.labels);
  regions.count = kept;
}

}  // namespace facet::grow
