#include "blobs/workspace_box.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "blobs/blob_support.hpp"
#include "facet/param_text.hpp"

namespace facet::blobs {

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

std::variant<facet::blobs::Workspace, std::string>
facet::ParamTraits<facet::blobs::Workspace>::parse(std::string_view text) {
  if (text.empty()) return blobs::Workspace{};
  const auto refused = [&](const std::string& why) {
    return "workspace must be empty or 'xmin,xmax,ymin,ymax,zmin,zmax' in metres with min < max, "
           "not '" +
           std::string(text) + "': " + why;
  };
  auto parsed = parse_number_list(text, 6);
  if (const auto* why = std::get_if<std::string>(&parsed)) return refused(*why);
  const NumberList& bounds = std::get<NumberList>(parsed);
  constexpr std::array<char, 3> kAxes{'x', 'y', 'z'};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (!(bounds.values[2 * axis] < bounds.values[2 * axis + 1])) {
      return refused(std::string(1, kAxes[axis]) + "min " + std::string(bounds.fields[2 * axis]) +
                     " is not below " + kAxes[axis] + "max " +
                     std::string(bounds.fields[2 * axis + 1]));
    }
  }
  const std::vector<float>& b = bounds.values;
  return blobs::Workspace{
      Eigen::AlignedBox3f(Eigen::Vector3f(b[0], b[2], b[4]), Eigen::Vector3f(b[1], b[3], b[5]))};
}

std::string facet::ParamTraits<facet::blobs::Workspace>::format(const blobs::Workspace& value) {
  if (!value.box) return "";
  const Eigen::AlignedBox3f& box = *value.box;
  const std::array<float, 6> bounds{box.min().x(), box.max().x(), box.min().y(),
                                    box.max().y(), box.min().z(), box.max().z()};
  return format_number_list(bounds);
}
