#include "partition/graph_cores.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

namespace facet::partition {
namespace {

// The value cv::compare writes for a pixel of a mask.
constexpr std::uint8_t kMaskSet = 255;

// Pairs (unclaimed region, node) that touch as 8-neighbours, sorted and unique.
std::vector<std::pair<std::int32_t, std::int32_t>> touching_faces(const cv::Mat& region,
                                                                  const cv::Mat& node_of_pixel) {
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  for (int v = 0; v < region.rows; ++v) {
    const auto* r = region.ptr<std::int32_t>(v);
    for (int u = 0; u < region.cols; ++u) {
      if (r[u] == 0) continue;
      for (int nv = std::max(v - 1, 0); nv <= std::min(v + 1, region.rows - 1); ++nv) {
        const auto* node = node_of_pixel.ptr<std::int32_t>(nv);
        for (int nu = std::max(u - 1, 0); nu <= std::min(u + 1, region.cols - 1); ++nu) {
          if (node[nu] >= 0) pairs.emplace_back(r[u], node[nu]);
        }
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// Whether half or more of the core's valid points lie within `tolerance_m` of `plane`.
bool lies_on(const std::vector<cv::Vec3f>& core_points, const FittedPlane& plane,
             double tolerance_m) {
  std::size_t on_plane = 0;
  for (const cv::Vec3f& p : core_points) {
    if (std::abs(plane.signed_distance_m(p[0], p[1], p[2])) <= tolerance_m) ++on_plane;
  }
  return !core_points.empty() && 2 * on_plane >= core_points.size();
}

// A view of the top left `size` of `buffer`, grown to at least `full` (reused from frame to
// frame, so that no image is allocated per frame: fresh pages cost more than the work here).
cv::Mat view_of(cv::Mat& buffer, cv::Size full, cv::Size size, int type) {
  if (buffer.type() != type || buffer.cols < full.width || buffer.rows < full.height) {
    buffer.create(full, type);
  }
  return buffer(cv::Rect(cv::Point(0, 0), size));
}

// The work of claim_unclaimed_cores on the rectangle that holds every unclaimed pixel and their
// neighbours; every image here is a view of that rectangle.
std::int32_t claim_cores_in(cv::Mat objects, const cv::Mat& unclaimed, const cv::Mat& points,
                            const cv::Mat& node_of_pixel, double fx_px,
                            const std::vector<FittedPlane>* planes, const CoreRule& rule,
                            cv::Size image_size, CoreBuffers& buffers, std::int32_t next_id) {
  // The image's edge is a border too: a region cut by it is measured from it.
  const cv::Size framed_full(image_size.width + 2, image_size.height + 2);
  const cv::Size framed_size(unclaimed.cols + 2, unclaimed.rows + 2);
  cv::Mat framed = view_of(buffers.framed, framed_full, framed_size, CV_8UC1);
  cv::copyMakeBorder(unclaimed, framed, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat framed_distance_px = view_of(buffers.distance_px, framed_full, framed_size, CV_32FC1);
  cv::distanceTransform(framed, framed_distance_px, cv::DIST_L2, cv::DIST_MASK_5);
  const cv::Mat distance_px = framed_distance_px(cv::Rect(1, 1, unclaimed.cols, unclaimed.rows));
  cv::Mat wide_enough = view_of(buffers.wide_enough, image_size, unclaimed.size(), CV_8UC1);
  cv::compare(distance_px, rule.radius_px, wide_enough, cv::CMP_GE);
  // Most frames have none: their unclaimed pixels are edge bands.
  if (cv::countNonZero(wide_enough) == 0) return next_id;
  cv::Mat core = view_of(buffers.core, image_size, unclaimed.size(), CV_32SC1);
  // One thread on purpose, not OpenCV's labelling: that runs a parallel_for of its own, which
  // would compete with the executor's threads.
  const int count =
      buffers.components.label(wide_enough, kMaskSet, 8, 0, core).count + 1;  // with label 0
  if (count <= 1) return next_id;

  // Per core: its widest point (largest distance to the border) and the 3D radius there.
  std::vector<float> widest_px(static_cast<std::size_t>(count), 0.0F);
  std::vector<double> radius_m(static_cast<std::size_t>(count), 0.0);
  for (int v = 0; v < core.rows; ++v) {
    const auto* c = core.ptr<std::int32_t>(v);
    const auto* d = distance_px.ptr<float>(v);
    const auto* p = points.ptr<cv::Vec3f>(v);
    for (int u = 0; u < core.cols; ++u) {
      const auto k = static_cast<std::size_t>(c[u]);
      if (k == 0 || d[u] <= widest_px[k] || !std::isfinite(p[u][2])) continue;
      widest_px[k] = d[u];
      radius_m[k] = fx_px > 0.0 ? d[u] * p[u][2] / fx_px : 0.0;
    }
  }
  std::vector<bool> wide(static_cast<std::size_t>(count), false);
  for (int c = 1; c < count; ++c) {
    const auto k = static_cast<std::size_t>(c);
    wide[k] = buffers.components.size_px(c) >= rule.min_px && radius_m[k] >= rule.radius_m;
  }

  // A wide core on the plane of a face beside it is that face's missing part.
  std::vector<bool> on_a_face(static_cast<std::size_t>(count), false);
  if (!node_of_pixel.empty() && planes != nullptr &&
      std::find(wide.begin(), wide.end(), true) != wide.end()) {
    cv::Mat region = view_of(buffers.region, image_size, unclaimed.size(), CV_32SC1);
    buffers.components.label(unclaimed, kMaskSet, 8, 0, region);
    const auto touching = touching_faces(region, node_of_pixel);
    std::vector<std::int32_t> region_of(static_cast<std::size_t>(count), 0);
    std::vector<std::vector<cv::Vec3f>> core_points(static_cast<std::size_t>(count));
    for (int v = 0; v < core.rows; ++v) {
      const auto* c = core.ptr<std::int32_t>(v);
      const auto* r = region.ptr<std::int32_t>(v);
      const auto* p = points.ptr<cv::Vec3f>(v);
      for (int u = 0; u < core.cols; ++u) {
        const auto k = static_cast<std::size_t>(c[u]);
        if (!wide[k]) continue;
        region_of[k] = r[u];
        if (std::isfinite(p[u][2])) core_points[k].push_back(p[u]);
      }
    }
    for (int c = 1; c < count; ++c) {
      const auto k = static_cast<std::size_t>(c);
      if (!wide[k]) continue;
      for (auto it = std::lower_bound(touching.begin(), touching.end(),
                                      std::make_pair(region_of[k], std::int32_t{-1}));
           it != touching.end() && it->first == region_of[k] && !on_a_face[k]; ++it) {
        const FittedPlane& plane = (*planes)[static_cast<std::size_t>(it->second)];
        on_a_face[k] = plane.valid && lies_on(core_points[k], plane, rule.plane_tolerance_m);
      }
    }
  }
  std::vector<std::int32_t> id_of(static_cast<std::size_t>(count), 0);
  for (int c = 1; c < count; ++c) {
    const auto k = static_cast<std::size_t>(c);
    if (wide[k] && !on_a_face[k]) id_of[k] = next_id++;
  }
  for (int v = 0; v < objects.rows; ++v) {
    auto* label = objects.ptr<std::int32_t>(v);
    const auto* c = core.ptr<std::int32_t>(v);
    for (int u = 0; u < objects.cols; ++u) {
      const std::int32_t id = id_of[static_cast<std::size_t>(c[u])];
      if (id != 0) label[u] = id;
    }
  }
  return next_id;
}

}  // namespace

std::int32_t claim_unclaimed_cores(cv::Mat& objects, const cv::Mat& blobs, const cv::Mat& points,
                                   double fx_px, const ClaimedFaces& faces, const CoreRule& rule,
                                   CoreBuffers& buffers, std::int32_t next_id) {
  if (rule.radius_px <= 0.0) return next_id;
  cv::compare(blobs, 0, buffers.in_blob, cv::CMP_GT);
  cv::compare(objects, 0, buffers.unclaimed, cv::CMP_EQ);
  cv::bitwise_and(buffers.unclaimed, buffers.in_blob, buffers.unclaimed);
  const cv::Mat& unclaimed = buffers.unclaimed;
  const cv::Rect bounds = cv::boundingRect(unclaimed);
  if (bounds.empty()) return next_id;
  // One pixel more on each side: the neighbours the touching test reads, and a border of
  // claimed pixels for the distance transform where the image goes on.
  const cv::Rect roi =
      (bounds + cv::Point(-1, -1) + cv::Size(2, 2)) & cv::Rect(0, 0, objects.cols, objects.rows);
  const cv::Mat node_of_pixel =
      faces.node_of_pixel != nullptr ? (*faces.node_of_pixel)(roi) : cv::Mat();
  return claim_cores_in(objects(roi), unclaimed(roi), points(roi), node_of_pixel, fx_px,
                        faces.planes, rule, objects.size(), buffers, next_id);
}

}  // namespace facet::partition
