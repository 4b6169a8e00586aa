#include "shape/grasp_rule.hpp"

namespace facet::shape {

GraspPrototype GraspRule::classify(const Eigen::Vector3d& full_extents_m) const {
  if (!full_extents_m.allFinite() || full_extents_m.maxCoeff() <= 0.0) return GraspPrototype::none;
  if (full_extents_m.maxCoeff() < pincer_max_extent_m) return GraspPrototype::pincer;
  if (full_extents_m.minCoeff() < precision_max_width_m) return GraspPrototype::precision;
  return GraspPrototype::power;
}

const GraspRuleParams kGraspRuleParams{
    Param<double>{
        "pincer_max_extent_m",
        0.04,
        "Grasp rule: an object whose largest full extent is below this gets a pincer grasp.",
        {.unit = "m", .min = 0.0, .max = 1.0, .origin = "small objects, about 4 cm"}},
    Param<double>{
        "precision_max_width_m",
        0.08,
        "Grasp rule: otherwise, an object whose smallest full extent is below this (it fits "
        "between the finger tips) gets a precision grasp; anything larger a power grasp.",
        {.unit = "m", .min = 0.0, .max = 1.0, .origin = "finger-tip span, about 8 cm"}}};

}  // namespace facet::shape
