#include "shape/superquadric_stage.hpp"

#include <chrono>

#include "shape/object_models.hpp"
#include "shape/pca_box.hpp"

namespace facet::shape {
namespace {

const Param<int> kMaxPoints{
    "max_points",
    200,
    "The fit uses a random subsample of this many of an object's points (all if fewer).",
    {.min = 22.0, .max = 1.0e6, .origin = "measured: ~1 ms per object"}};
const Param<int> kSeed{"seed",
                       1,
                       "Seed of the subsample; the same seed gives the same fit.",
                       {.min = 0.0, .max = 2.0e9}};
const Param<int> kMaxIterations{
    "max_iterations", 25, "Levenberg-Marquardt iterations at most.", {.min = 1.0, .max = 1000.0}};
const Param<double> kSupportWeight{
    "support_weight",
    1.0,
    "Weight of the contact term (lowest point on the support plane), relative to all points "
    "together; 0 disables it.",
    {.min = 0.0, .max = 100.0}};
const Param<double> kSizePriorWeight{
    "size_prior_weight",
    0.1,
    "Pull of each log size towards the initial box, as if every point were off by weight x mean "
    "size x change of log size: it keeps sizes the points do not constrain (the unseen back) "
    "from drifting; 0 disables it.",
    {.min = 0.0, .max = 10.0}};
const Param<bool> kExtendWithoutPlane{
    "extend_without_plane", true,
    "Without a support plane, start from the PCA box made as deep (along the viewing ray) as its "
    "smaller other extent, grown away from the camera."};

// Each object gets its own subsample stream, so adding an object does not change the others.
std::uint64_t object_seed(std::uint64_t seed, std::int32_t id) {
  return seed ^ (static_cast<std::uint64_t>(id) * 0x9E3779B97F4A7C15ULL);
}

// How the frame's fits ended, so that a tolerance or an iteration limit that cuts fits short
// shows in `facet run --json` and in comparisons. An object with too few points has no fit and
// no summary to count (0 iterations).
void report_solver_stops(ProcessContext& ctx, const std::vector<algo::SolverSummary>& summaries) {
  int converged = 0;
  int at_limit = 0;
  int stalled = 0;
  int run = 0;
  std::int64_t iterations = 0;
  for (const algo::SolverSummary& summary : summaries) {
    if (summary.iterations == 0) continue;
    ++run;
    iterations += summary.iterations;
    if (summary.converged()) {
      ++converged;
    } else if (summary.stop == algo::SolverStop::max_iterations) {
      ++at_limit;
    } else {
      ++stalled;
    }
  }
  ctx.metric("fits_converged", converged);
  ctx.metric("fits_at_iteration_limit", at_limit);
  ctx.metric("fits_stalled", stalled);
  ctx.metric("mean_iterations", run > 0 ? static_cast<double>(iterations) / run : 0.0);
}

}  // namespace

StageSpec SuperquadricStage::spec() {
  StageSpec spec(
      "shape.superquadric",
      "Superquadric (a1..a3, eps1, eps2, pose) of each object, fitted to its visible points.\n"
      "Levenberg-Marquardt over size, shape and pose together (sizes through log, shapes through "
      "a sigmoid onto [0.1, 2]), residual = radial distance |p|(1 - F^(-eps1/2)). Initial pose "
      "and size: with a support plane, a box standing on the plane (z = plane normal, footprint "
      "from the points' shadow, top = highest point), and the fit also pulls the "
      "superquadric's lowest point onto the plane; without one, the PCA box grown away from the "
      "camera (extend_without_plane). superquadric.residual = RMS radial distance (m) over the "
      "points used. The box output is the plain PCA box. The grasp prototype uses the "
      "superquadric's full extents. Metrics: objects, mean_residual_m, fit_ms, and how the "
      "fits of the frame ended: fits_converged (the cost or the step fell below its "
      "tolerance), fits_at_iteration_limit (max_iterations reached first), fits_stalled (no "
      "step lowered the cost any more, or the step was not finite), mean_iterations.");
  return spec
      .declare(kObjectStage, kMaxPoints, kSeed, kMaxIterations, kSupportWeight, kSizePriorWeight,
               kExtendWithoutPlane, kGraspRuleParams)
      .concurrency(Concurrency::clonable);
}

algo::SolverSummary SuperquadricStage::fit_object(ObjectGeometry& geometry) const {
  ObjectModel& model = geometry.model;
  model.box.residual_m = box_surface_rms_m(model.box, geometry.points_m);
  OrientedBox initial = model.box;
  if (geometry.support != nullptr) {
    initial = fit_supported_box(geometry.points_m, *geometry.support);
  } else if (extend_without_plane_) {
    initial = extend_box_away_from_camera(model.box);
  }
  SuperquadricFitOptions options = fit_options_;
  options.seed = object_seed(fit_options_.seed, model.id);
  const Plane* contact = fit_options_.support_weight > 0.0 ? geometry.support : nullptr;
  const SuperquadricFit fit = fit_superquadric(geometry.points_m, initial, contact, options);
  model.superquadric = fit.superquadric;
  model.grasp = grasp_rule_.classify(
      2.0 * (model.superquadric.valid ? model.superquadric.size_m : model.box.half_extents_m));
  return fit.summary;
}

SuperquadricStage::SuperquadricStage(const Params& params)
    : support_tolerance_m_(kObjectStage.support_tolerance_m(params)),
      support_max_gap_m_(kObjectStage.support_max_gap_m(params)),
      extend_without_plane_(kExtendWithoutPlane(params)),
      grasp_rule_(kGraspRuleParams(params)) {
  fit_options_.max_points = kMaxPoints(params);
  fit_options_.seed = static_cast<std::uint64_t>(kSeed(params));
  fit_options_.solver.max_iterations = kMaxIterations(params);
  fit_options_.support_weight = kSupportWeight(params);
  fit_options_.size_prior_weight = kSizePriorWeight(params);
}

void SuperquadricStage::process(ProcessContext& ctx) {
  const LabelImage& labels = kObjectStage.objects(ctx);
  const PointImage& points = kObjectStage.points(ctx);
  const SupportPlanes* planes = kObjectStage.planes(ctx);
  const auto start = std::chrono::steady_clock::now();

  auto list = of_frame<ObjectList>(labels);
  std::vector<ObjectGeometry> geometries =
      describe_objects(labels, points, planes, support_tolerance_m_, support_max_gap_m_);
  // Objects are fitted independently (each with its own seed), one or more per worker.
  std::vector<algo::SolverSummary> summaries(geometries.size());
  ctx.parallel_for(static_cast<std::int64_t>(geometries.size()), 1,
                   [&](std::int64_t begin, std::int64_t end) {
                     for (std::int64_t i = begin; i < end; ++i) {
                       const auto object = static_cast<std::size_t>(i);
                       summaries[object] = fit_object(geometries[object]);
                     }
                   });
  double residual_sum_m = 0.0;
  int fitted = 0;
  for (ObjectGeometry& geometry : geometries) {
    if (geometry.model.superquadric.valid) {
      residual_sum_m += geometry.model.superquadric.residual;
      ++fitted;
    }
    list.objects.push_back(std::move(geometry.model));
  }
  const double fit_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ctx.metric("objects", static_cast<double>(list.objects.size()));
  ctx.metric("mean_residual_m", fitted > 0 ? residual_sum_m / fitted : 0.0);
  ctx.metric("fit_ms", fit_ms);
  report_solver_stops(ctx, summaries);
  kObjectStage.models(ctx, std::move(list));
}

}  // namespace facet::shape
