#pragma once
// shape.superquadric: per object, a superquadric fitted to its visible points by
// Levenberg–Marquardt over size, shape and pose (paper sec. III-E), with the unseen back side
// closed by the support plane when one is known.

#include <cstdint>

#include "facet/stage.hpp"
#include "shape/grasp_rule.hpp"
#include "shape/object_models.hpp"
#include "shape/superquadric_fit.hpp"

namespace facet::shape {

class SuperquadricStage final : public Stage {
 public:
  static StageSpec spec();
  explicit SuperquadricStage(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  // Box residual, initial box, superquadric and grasp prototype of one object, in place.
  algo::SolverSummary fit_object(ObjectGeometry& geometry) const;

  double support_tolerance_m_;
  double support_max_gap_m_;
  bool extend_without_plane_;
  SuperquadricFitOptions fit_options_;
  GraspRule grasp_rule_;
};

}  // namespace facet::shape
