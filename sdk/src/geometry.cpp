#include "facet/types/geometry.hpp"

namespace facet {

std::string_view to_string(GraspPrototype grasp) noexcept {
  switch (grasp) {
    case GraspPrototype::none:
      return "none";
    case GraspPrototype::power:
      return "power";
    case GraspPrototype::precision:
      return "precision";
    case GraspPrototype::pincer:
      return "pincer";
  }
  return "none";
}

}  // namespace facet
