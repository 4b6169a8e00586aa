#include "planes/world_up.hpp"

#include <cmath>
#include <numbers>
#include <span>

#include "facet/param_text.hpp"

namespace facet::planes {

int dominant_horizontal(const std::vector<algo::Plane>& candidates,
                        const Eigen::Vector3f& reference, double max_angle_deg) {
  const double min_cos = std::cos(max_angle_deg * std::numbers::pi / 180.0);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].normal.dot(reference) >= min_cos) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace facet::planes

std::variant<facet::planes::WorldUp, std::string> facet::ParamTraits<facet::planes::WorldUp>::parse(
    std::string_view text) {
  if (text == "auto") return planes::WorldUp{};
  const auto refused = [&](const std::string& why) {
    return "up must be 'auto' or a non-zero vector 'x,y,z', not '" + std::string(text) +
           "': " + why;
  };
  auto parsed = parse_number_list(text, 3);
  if (const auto* why = std::get_if<std::string>(&parsed)) return refused(*why);
  const std::vector<float>& values = std::get<NumberList>(parsed).values;
  const Eigen::Vector3f up(values[0], values[1], values[2]);
  if (!(up.norm() > 0.0F)) return refused("a zero vector has no direction");
  return planes::WorldUp{up.normalized()};
}

std::string facet::ParamTraits<facet::planes::WorldUp>::format(const planes::WorldUp& value) {
  if (!value.direction) return "auto";
  const Eigen::Vector3f& up = *value.direction;
  return format_number_list(std::span<const float>(up.data(), 3));
}
