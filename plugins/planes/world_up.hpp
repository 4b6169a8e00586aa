#pragma once
// World up in the camera frame: given as a parameter, or taken from the dominant horizontal plane.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "facet/algo/plane.hpp"

namespace facet::planes {

// "auto" gives nothing; "x,y,z" (camera frame, any length > 0) gives the unit vector. Throws
// std::invalid_argument for anything else.
std::optional<Eigen::Vector3f> parse_up(const std::string& text);

// The index of the dominant horizontal candidate: the first (largest) one whose normal is within
// max_angle_deg of `reference` (the given world up, or the camera's up -y as a prior); -1 if none.
int dominant_horizontal(const std::vector<algo::Plane>& candidates,
                        const Eigen::Vector3f& reference, double max_angle_deg);

}  // namespace facet::planes
