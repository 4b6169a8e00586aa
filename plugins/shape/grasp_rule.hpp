#pragma once
// Which grasp prototype fits an object, from its size alone (the paper picks power, precision or
// pincer "based on object size").

#include <Eigen/Core>

#include "facet/param.hpp"
#include "facet/stage_spec.hpp"
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

  static void declare(StageSpec& spec);
  static GraspRule from(const Params& params);
};

}  // namespace facet::shape
