#pragma once
// Which grasp prototype fits an object, from its size alone (the paper picks power, precision or
// pincer "based on object size").

#include <Eigen/Core>

#include "facet/contract.hpp"
#include "facet/types/geometry.hpp"

namespace facet::shape {

// Full extents (not half), metres:
//   largest extent < pincer_max_extent_m     → pincer    (thumb and index finger tips)
//   smallest extent < precision_max_width_m  → precision (fits between the finger tips)
//   otherwise                                → power     (whole hand around the object)
// Zero or non-finite extents (no points) → none.
struct GraspRule {
  double pincer_max_extent_m = 0.04;
  double precision_max_width_m = 0.08;

  GraspPrototype classify(const Eigen::Vector3d& full_extents_m) const;
};

// The rule's two thresholds as parameters of both shape stages: `spec.declare(kGraspRuleParams)`,
// `kGraspRuleParams(params)`.
struct GraspRuleParams {
  Param<double> pincer_max_extent_m;
  Param<double> precision_max_width_m;

  void declare_in(StageSpec& spec) const {
    spec.declare(pincer_max_extent_m, precision_max_width_m);
  }
  GraspRule operator()(const Params& params) const {
    return {pincer_max_extent_m(params), precision_max_width_m(params)};
  }
};
extern const GraspRuleParams kGraspRuleParams;

}  // namespace facet::shape
