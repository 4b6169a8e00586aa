#include "blobs/workspace_box.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "blobs/blob_support.hpp"

namespace facet::blobs {

std::optional<Eigen::AlignedBox3f> parse_workspace(const std::string& text) {
  if (text.empty()) return std::nullopt;
  std::istringstream in(text);
  std::array<float, 6> bounds{};
  bool ok = true;
  for (std::size_t i = 0; i < bounds.size() && ok; ++i) {
    char comma = ',';
    if (i > 0) in >> comma;
    in >> bounds[i];
    ok = !in.fail() && comma == ',' && std::isfinite(bounds[i]);
  }
  ok = ok && (in >> std::ws).eof();
  for (std::size_t axis = 0; axis < 3 && ok; ++axis)
    ok = bounds[2 * axis] < bounds[2 * axis + 1];
  if (!ok) {
    throw std::invalid_argument(
        "workspace must be empty or 'xmin,xmax,ymin,ymax,zmin,zmax' in metres with min < max, "
        "not '" +
        text + "'");
  }
  return Eigen::AlignedBox3f(Eigen::Vector3f(bounds[0], bounds[2], bounds[4]),
                             Eigen::Vector3f(bounds[1], bounds[3], bounds[5]));
}

std::int32_t drop_blobs_outside(EuclideanRegions& blobs, const cv::Mat& xyz,
                                const Eigen::AlignedBox3f& box) {
  if (blobs.count == 0) return 0;
  const auto count = static_cast<std::size_t>(blobs.count) + 1;
  std::vector<Eigen::Vector3d> sum(count, Eigen::Vector3d::Zero());
  std::vector<std::int64_t> size_px(count, 0);
  const auto* label = blobs.labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = blobs.labels.total();
  for (std::size_t i = 0; i < total; ++i) {
    const auto id = static_cast<std::size_t>(label[i]);
    if (id == 0) continue;
    sum[id] += Eigen::Vector3d(point[3 * i], point[3 * i + 1], point[3 * i + 2]);
    ++size_px[id];
  }
  std::vector<char> keep(count, 0);
  for (std::size_t id = 1; id < count; ++id) {
    if (size_px[id] == 0) continue;
    const Eigen::Vector3d centroid = sum[id] / static_cast<double>(size_px[id]);
    keep[id] = box.contains(centroid.cast<float>()) ? 1 : 0;
  }
  return keep_blobs(blobs, keep);
}

}  // namespace facet::blobs
