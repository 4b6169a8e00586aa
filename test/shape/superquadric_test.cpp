// shape.superquadric on ray-cast objects standing on a table: the fit recovers size, shape and the
// unseen back side that a PCA box of the visible points misses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "facet/testing/stage_runner.hpp"
#include "shape/pca_box_stage.hpp"
#include "shape/superquadric_stage.hpp"
#include "tabletop_scene.hpp"

namespace facet::shape {
namespace {

using test::render_tabletop;
using test::TabletopScene;
using test::TabletopShape;

ObjectList run_superquadric(const TabletopScene& scene, bool with_planes, std::int64_t seed = 1) {
  testing::StageRunner<SuperquadricStage> runner({{"seed", seed}});
  runner.set_input("objects", Packet::make(scene.objects));
  runner.set_input("points", Packet::make(scene.points));
  if (with_planes) runner.set_input("planes", Packet::make(scene.planes));
  runner.run();
  return runner.output<ObjectList>("objects");
}

ObjectModel fit_one(const TabletopScene& scene, bool with_planes = true, std::int64_t seed = 1) {
  const ObjectList list = run_superquadric(scene, with_planes, seed);
  EXPECT_EQ(list.objects.size(), 1u);
  return list.objects.empty() ? ObjectModel{} : list.objects.front();
}

ObjectModel run_pca_box(const TabletopScene& scene) {
  testing::StageRunner<PcaBoxStage> runner;
  runner.set_input("objects", Packet::make(scene.objects));
  runner.set_input("points", Packet::make(scene.points));
  runner.set_input("planes", Packet::make(scene.planes));
  runner.run();
  return runner.output<ObjectList>("objects").objects.at(0);
}

// Full extent of a box-like model (pose, half sizes) along a camera-frame direction.
double extent_along(const Eigen::Isometry3d& pose, const Eigen::Vector3d& half_m,
                    const Eigen::Vector3d& direction) {
  return 2.0 * (pose.linear().transpose() * direction).cwiseAbs().dot(half_m);
}

TEST(Superquadric, SeenFromAboveRecoversTheHeightThatThePcaBoxMisses) {
  // Straight down onto the box: the camera sees only the top face.
  const Eigen::Vector3d half_m(0.06, 0.035, 0.05);
  const TabletopScene scene =
      render_tabletop(TabletopShape::box, half_m, 90.0, 25.0, {0.0, 0.0, 0.9});
  const ObjectModel sq = fit_one(scene);
  const ObjectModel box = run_pca_box(scene);
  ASSERT_TRUE(sq.superquadric.valid);
  const Eigen::Vector3d view = scene.object_pose.translation().normalized();
  const double true_depth_m = 2.0 * half_m.z();
  EXPECT_LT(extent_along(box.box.pose, box.box.half_extents_m, view), 0.2 * true_depth_m);
  EXPECT_NEAR(extent_along(sq.superquadric.pose, sq.superquadric.size_m, view), true_depth_m,
              0.1 * true_depth_m);
  // The PCA box sits on the visible top; the superquadric's centre is inside the object.
  EXPECT_GT((box.box.pose.translation() - scene.object_pose.translation()).norm(), 0.04);
  EXPECT_LT((sq.superquadric.pose.translation() - scene.object_pose.translation()).norm(), 0.005);
  EXPECT_EQ(sq.support_plane, 1);
}

// Both shape stages copy the support plane's equation into the object, in the plane's own sign
// convention, and keep the frame's camera, so the object list alone suffices to a grasp planner.
TEST(Superquadric, BothShapeStagesCarryTheSupportPlaneEquationAndTheCamera) {
  const TabletopScene scene =
      render_tabletop(TabletopShape::box, {0.06, 0.035, 0.05}, 60.0, 25.0, {0.0, 0.0, 0.9});
  const Plane& table = scene.planes.planes.front();
  const ObjectList list = run_superquadric(scene, true);
  ASSERT_EQ(list.objects.size(), 1u);
  EXPECT_EQ(list.camera, scene.objects.camera);
  for (const ObjectModel& object : {list.objects.front(), run_pca_box(scene)}) {
    ASSERT_EQ(object.support_plane, table.id);
    EXPECT_EQ(object.support_normal, table.normal);
    EXPECT_EQ(object.support_offset_m, table.offset_m);
    EXPECT_NEAR(object.support_normal.norm(), 1.0, 1e-12);
    // Towards the camera: the camera (the origin) is on the positive side, the object above.
    EXPECT_GT(object.support_offset_m, 0.0);
    EXPECT_GT(object.support_normal.dot(object.centroid_m) + object.support_offset_m, 0.0);
  }
}

TEST(Superquadric, BoxSizesShapeAndCentreFromAnObliqueView) {
  const Eigen::Vector3d half_m(0.06, 0.035, 0.05);
  for (const double pitch_deg : {35.0, 50.0, 65.0}) {
    SCOPED_TRACE(pitch_deg);
    const TabletopScene scene = render_tabletop(TabletopShape::box, half_m, pitch_deg);
    const ObjectModel sq = fit_one(scene);
    ASSERT_TRUE(sq.superquadric.valid);
    const Superquadric& q = sq.superquadric;
    EXPECT_NEAR(q.size_m.x(), half_m.x(), 0.006);
    EXPECT_NEAR(q.size_m.y(), half_m.y(), 0.01);  // the back face is never seen
    EXPECT_NEAR(q.size_m.z(), half_m.z(), 0.003);
    EXPECT_LT(q.epsilon1, 0.3);
    EXPECT_LT(q.epsilon2, 0.3);
    EXPECT_LT((q.pose.translation() - scene.object_pose.translation()).norm(), 0.012);
    EXPECT_LT(q.residual, 0.002);
    // The long axis found is the box's long axis (up to sign).
    EXPECT_GT(std::abs(q.pose.linear().col(0).dot(scene.object_pose.linear().col(0))), 0.99);
  }
}

TEST(Superquadric, CylinderHasARoundCrossSectionAndFlatCaps) {
  const Eigen::Vector3d half_m(0.04, 0.04, 0.07);
  const TabletopScene scene = render_tabletop(TabletopShape::cylinder, half_m, 45.0);
  const ObjectModel sq = fit_one(scene);
  ASSERT_TRUE(sq.superquadric.valid);
  const Superquadric& q = sq.superquadric;
  EXPECT_NEAR(q.epsilon2, 1.0, 0.15);
  EXPECT_LT(q.epsilon1, 0.3);
  EXPECT_NEAR(q.size_m.x(), 0.04, 0.004);
  EXPECT_NEAR(q.size_m.y(), 0.04, 0.004);
  EXPECT_NEAR(q.size_m.z(), 0.07, 0.003);
  EXPECT_LT((q.pose.translation() - scene.object_pose.translation()).norm(), 0.005);
}

TEST(Superquadric, SameSeedSameFitDifferentSeedStillClose) {
  const TabletopScene scene = render_tabletop(TabletopShape::box, {0.06, 0.035, 0.05}, 50.0);
  const ObjectModel a = fit_one(scene, true, 7);
  const ObjectModel b = fit_one(scene, true, 7);
  const ObjectModel c = fit_one(scene, true, 8);
  EXPECT_EQ(a.superquadric.size_m, b.superquadric.size_m);
  EXPECT_EQ(a.superquadric.pose.matrix(), b.superquadric.pose.matrix());
  EXPECT_EQ(a.superquadric.epsilon1, b.superquadric.epsilon1);
  EXPECT_EQ(a.superquadric.residual, b.superquadric.residual);
  EXPECT_LT((a.superquadric.size_m - c.superquadric.size_m).norm(), 0.005);
}

TEST(Superquadric, WithoutPlanesStillFitsTheVisibleShape) {
  const TabletopScene scene = render_tabletop(TabletopShape::box, {0.06, 0.035, 0.05}, 50.0);
  const ObjectModel sq = fit_one(scene, false);
  ASSERT_TRUE(sq.superquadric.valid);
  EXPECT_EQ(sq.support_plane, 0);
  EXPECT_EQ(sq.support_normal, Eigen::Vector3d::Zero());
  EXPECT_EQ(sq.support_offset_m, 0.0);
  EXPECT_LT(sq.superquadric.residual, 0.003);
  EXPECT_LT((sq.centroid_m - scene.object_pose.translation()).norm(), 0.05);
}

TEST(Superquadric, EmptyTinyAndInvalidObjectsDoNotCrash) {
  const TabletopScene scene = render_tabletop(TabletopShape::box, {0.06, 0.035, 0.05}, 50.0);
  // No object at all.
  TabletopScene empty = scene;
  // A new buffer: assigning cv::Mat::zeros() would write into the one `scene` shares.
  empty.objects.labels = cv::Mat(scene.objects.labels.size(), CV_32SC1, cv::Scalar(0));
  EXPECT_TRUE(run_superquadric(empty, true).objects.empty());
  // Object 2: three pixels. Object 3: only NaN points.
  TabletopScene mixed = scene;
  mixed.objects.labels = scene.objects.labels.clone();
  mixed.objects.count = 3;
  mixed.points.points = scene.points.points.clone();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int u = 0; u < 3; ++u)
    mixed.objects.labels.at<int>(5, u) = 2;
  for (int u = 0; u < 10; ++u) {
    mixed.objects.labels.at<int>(470, u) = 3;
    mixed.points.points.at<cv::Vec3f>(470, u) = cv::Vec3f(nan, nan, nan);
  }
  const ObjectList list = run_superquadric(mixed, true);
  ASSERT_EQ(list.objects.size(), 3u);
  EXPECT_TRUE(list.objects[0].superquadric.valid);
  EXPECT_EQ(list.objects[1].id, 2);
  EXPECT_EQ(list.objects[1].pixel_count, 3);
  EXPECT_FALSE(list.objects[1].superquadric.valid);
  EXPECT_EQ(list.objects[2].id, 3);
  EXPECT_EQ(list.objects[2].pixel_count, 10);
  EXPECT_FALSE(list.objects[2].superquadric.valid);
  EXPECT_EQ(list.objects[2].grasp, GraspPrototype::none);
}

double metric_of(const std::vector<Metric>& metrics, const std::string& name) {
  for (const Metric& metric : metrics)
    if (metric.name == name) return metric.value;
  ADD_FAILURE() << "no metric " << name;
  return std::numeric_limits<double>::quiet_NaN();
}

TEST(Superquadric, ReportsWhyItsFitsEnded) {
  const TabletopScene scene = render_tabletop(TabletopShape::box, {0.06, 0.035, 0.05}, 50.0);
  // Object 2: three pixels, too few for a fit, so it counts under no stop reason.
  TabletopScene two = scene;
  two.objects.labels = scene.objects.labels.clone();
  two.objects.count = 2;
  for (int u = 0; u < 3; ++u)
    two.objects.labels.at<int>(5, u) = 2;
  const auto run = [&](std::int64_t max_iterations) {
    testing::StageRunner<SuperquadricStage> runner({{"max_iterations", max_iterations}});
    runner.set_input("objects", Packet::make(two.objects));
    runner.set_input("points", Packet::make(two.points));
    runner.set_input("planes", Packet::make(two.planes));
    runner.run();
    return runner.metrics();
  };
  const auto full = run(200);
  EXPECT_EQ(metric_of(full, "fits_converged"), 1.0);
  EXPECT_EQ(metric_of(full, "fits_at_iteration_limit"), 0.0);
  EXPECT_EQ(metric_of(full, "fits_stalled"), 0.0);
  EXPECT_GT(metric_of(full, "mean_iterations"), 1.0);
  EXPECT_LT(metric_of(full, "mean_iterations"), 200.0);
  // One step cannot reach the tolerance from the initial box.
  const auto cut = run(1);
  EXPECT_EQ(metric_of(cut, "fits_converged"), 0.0);
  EXPECT_EQ(metric_of(cut, "fits_at_iteration_limit"), 1.0);
  EXPECT_EQ(metric_of(cut, "mean_iterations"), 1.0);
}

}  // namespace
}  // namespace facet::shape
