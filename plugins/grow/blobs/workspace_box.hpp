#pragma once
// The optional task space of grow.blobs: an axis-aligned box in the camera frame (metres) that
// an object's centroid must lie in, e.g. the part of a table a robot arm can reach.

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "blobs/euclidean_regions.hpp"
#include "facet/contract.hpp"

namespace facet::blobs {

// The `workspace` parameter of grow.blobs: the box, or nothing for no task space.
struct Workspace {
  std::optional<Eigen::AlignedBox3f> box;
};

// Removes the blobs whose centroid lies outside `box` and renumbers the rest. Returns how many
// were removed.
std::int32_t drop_blobs_outside(EuclideanRegions& blobs, const cv::Mat& xyz,
                                const Eigen::AlignedBox3f& box);

}  // namespace facet::blobs

// Written "" (no box) or "xmin,xmax,ymin,ymax,zmin,zmax" with min < max on each axis. Anything
// else is refused with a message that quotes the text.
template <>
struct facet::ParamTraits<facet::blobs::Workspace> {
  static std::variant<facet::blobs::Workspace, std::string> parse(std::string_view text);
  static std::string format(const facet::blobs::Workspace& value);
};
