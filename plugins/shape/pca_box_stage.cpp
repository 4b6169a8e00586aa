#include "shape/pca_box_stage.hpp"

#include <chrono>

#include "shape/object_models.hpp"
#include "shape/pca_box.hpp"

namespace facet::shape {

StageSpec PcaBoxStage::spec() {
  StageSpec spec("shape.pca_box",
                 "Oriented box of each object from PCA of its visible points.\n"
                 "Axes = principal axes (x = largest spread), extent = the points' min/max along "
                 "them. box.residual_m = RMS distance of the points to the box surface. The box "
                 "covers only what the camera saw, so it is too thin along the viewing ray; "
                 "shape.superquadric accounts for the unseen back. The grasp prototype uses the "
                 "box's full extents. Metrics: objects, mean_residual_m, fit_ms.");
  return spec.declare(kObjectStage, kGraspRuleParams).concurrency(Concurrency::clonable);
}

PcaBoxStage::PcaBoxStage(const Params& params)
    : support_tolerance_m_(kObjectStage.support_tolerance_m(params)),
      support_max_gap_m_(kObjectStage.support_max_gap_m(params)),
      grasp_rule_(kGraspRuleParams(params)) {}

void PcaBoxStage::process(ProcessContext& ctx) {
  const LabelImage& labels = kObjectStage.objects(ctx);
  const PointImage& points = kObjectStage.points(ctx);
  const SupportPlanes* planes = kObjectStage.planes(ctx);
  const auto start = std::chrono::steady_clock::now();

  auto list = of_frame<ObjectList>(labels);
  double residual_sum_m = 0.0;
  for (ObjectGeometry& geometry :
       describe_objects(labels, points, planes, support_tolerance_m_, support_max_gap_m_)) {
    ObjectModel& model = geometry.model;
    model.box.residual_m = box_surface_rms_m(model.box, geometry.points_m);
    model.grasp = grasp_rule_.classify(2.0 * model.box.half_extents_m);
    residual_sum_m += model.box.residual_m;
    list.objects.push_back(std::move(model));
  }
  const double fit_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const auto count = static_cast<double>(list.objects.size());
  ctx.metric("objects", count);
  ctx.metric("mean_residual_m", count > 0 ? residual_sum_m / count : 0.0);
  ctx.metric("fit_ms", fit_ms);
  kObjectStage.models(ctx, std::move(list));
}

}  // namespace facet::shape
