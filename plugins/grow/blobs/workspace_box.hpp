#pragma once
// The optional task space of grow.blobs: an axis-aligned box in the camera frame (metres) that
// an object's centroid must lie in, e.g. the part of a table a robot arm can reach.

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "blobs/euclidean_regions.hpp"

namespace facet::blobs {

// "" = no box; otherwise "xmin,xmax,ymin,ymax,zmin,zmax" with min < max on each axis. Throws
// std::invalid_argument naming the text otherwise.
std::optional<Eigen::AlignedBox3f> parse_workspace(const std::string& text);

// Removes the blobs whose centroid lies outside `box` and renumbers the rest. Returns how many
// were removed.
std::int32_t drop_blobs_outside(EuclideanRegions& blobs, const cv::Mat& xyz,
                                const Eigen::AlignedBox3f& box);

}  // namespace facet::blobs
