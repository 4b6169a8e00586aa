#pragma once
// World up in the camera frame: given as a parameter, or taken from the dominant horizontal plane.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "facet/algo/plane.hpp"
#include "facet/contract.hpp"

namespace facet::planes {

// The `up` parameter of planes.support: a unit vector in the camera frame, or nothing for auto
// (taken from the dominant horizontal plane each frame).
struct WorldUp {
  std::optional<Eigen::Vector3f> direction;
};

// The index of the dominant horizontal candidate: the first (largest) one whose normal is within
// max_angle_deg of `reference` (the given world up, or the camera's up -y as a prior); -1 if none.
int dominant_horizontal(const std::vector<algo::Plane>& candidates,
                        const Eigen::Vector3f& reference, double max_angle_deg);

}  // namespace facet::planes

// Written "auto" (no direction) or "x,y,z" (camera frame, any length > 0: parsed to the unit
// vector). Anything else is refused with a message that quotes the text.
template <>
struct facet::ParamTraits<facet::planes::WorldUp> {
  static std::variant<facet::planes::WorldUp, std::string> parse(std::string_view text);
  static std::string format(const facet::planes::WorldUp& value);
};
