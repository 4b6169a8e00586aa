#include "planes/world_up.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace facet::planes {

std::optional<Eigen::Vector3f> parse_up(const std::string& text) {
  if (text == "auto") return std::nullopt;
  std::istringstream in(text);
  Eigen::Vector3f up;
  char comma1 = 0;
  char comma2 = 0;
  in >> up.x() >> comma1 >> up.y() >> comma2 >> up.z();
  if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() || !up.allFinite() ||
      !(up.norm() > 0.0F)) {
    throw std::invalid_argument("up must be 'auto' or a non-zero vector 'x,y,z', not '" + text +
                                "'");
  }
  return up.normalized();
}

int dominant_horizontal(const std::vector<algo::Plane>& candidates,
                        const Eigen::Vector3f& reference, double max_angle_deg) {
  const double min_cos = std::cos(max_angle_deg * std::numbers::pi / 180.0);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].normal.dot(reference) >= min_cos) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace facet::planes
