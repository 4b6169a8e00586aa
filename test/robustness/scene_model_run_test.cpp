// The scene model (docs/planes.md) through the whole tabletop graph, on rendered frames: flat
// objects lying on the table are objects, things standing on them are objects of their own, the
// table's front edge and a far wall broken into disparity steps are background. The rows
// "a stack of three books", "a table covered by a board" and "no objects but a book" of README's
// bad-input table come from here.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "bad_input_scenes.hpp"
#include "tabletop_run.hpp"

namespace facet::test {
namespace {

const TabletopFrame kTable;

// Kinect v1 depth: disparity in steps of 1/8 pixel (IR focal length 580 px, baseline 7.5 cm),
// then millimetres, so that a far wall shows the sensor's depth bands (11 mm apart at 2 m,
// 26 mm at 3 m).
cv::Mat kinect_quantised_mm(const RenderedScene& scene, double max_range_m = 4.0) {
  constexpr double kFocalBaseline = 580.0 * 0.075;
  cv::Mat out = cv::Mat::zeros(scene.depth_m.size(), CV_16UC1);
  for (int v = 0; v < out.rows; ++v) {
    for (int u = 0; u < out.cols; ++u) {
      const double z = scene.depth_m.at<float>(v, u);
      if (!(z > 0.0) || z > max_range_m) continue;
      const double steps = std::round(8.0 * kFocalBaseline / z);
      out.at<std::uint16_t>(v, u) =
          static_cast<std::uint16_t>(std::lround(1000.0 * 8.0 * kFocalBaseline / steps));
    }
  }
  return out;
}

FrameResult run_one(const RenderedScene& scene, bool quantised = false,
                    const std::vector<std::pair<std::string, std::string>>& params = {}) {
  Dataset data(kinect_camera());
  data.add("frame", quantised ? kinect_quantised_mm(scene) : depth_mm(scene));
  const TabletopRun run = run_tabletop(data, params);
  EXPECT_TRUE(run.completed()) << run.error;
  return run.frame("frame");
}

// Object ids of the scene are the primitives' order: the table (and the structure) first.
int found_alone(const RenderedScene& scene, int first_object, int last_object,
                const cv::Mat& labels) {
  cv::Mat objects = scene.object.clone();
  objects.setTo(0, scene.object < first_object);
  return objects_found_alone(objects, last_object, labels);
}

TEST(TabletopSceneModel, BookAloneIsOneObject) {
  for (const double thickness_m : {0.015, 0.03}) {
    SceneBuilder scene;
    scene.plane(kTable.table_point, kTable.up);
    kTable.box_on_table(scene, -0.05, 0.05, {0.13, 0.09, 0.5 * thickness_m});
    const RenderedScene rendered = scene.render();
    const FrameResult frame = run_one(rendered);
    EXPECT_EQ(frame.objects(), 1u) << thickness_m << " m\n" << frame.json;
    EXPECT_EQ(found_alone(rendered, 2, 2, frame.labels), 1) << thickness_m << " m";
  }
}

TEST(TabletopSceneModel, BoxOnABookIsTwoObjects) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                                // 1
  kTable.box_on_table(scene, -0.05, 0.05, {0.13, 0.09, 0.015});              // 2: book
  scene.box(kTable.on_table(-0.05, 0.05, 0.03 + 0.06), {0.04, 0.05, 0.06});  // 3: on it
  kTable.box_on_table(scene, 0.25, 0.0, {0.05, 0.04, 0.08});                 // 4: beside
  const RenderedScene rendered = scene.render();
  const FrameResult frame = run_one(rendered);
  EXPECT_EQ(frame.objects(), 3u) << frame.json;
  EXPECT_EQ(found_alone(rendered, 2, 4, frame.labels), 3);
}

TEST(TabletopSceneModel, ThreeBooksStacked) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                                    // 1
  kTable.box_on_table(scene, 0.0, 0.05, {0.14, 0.10, 0.015});                    // 2
  scene.box(kTable.on_table(0.02, 0.03, 0.03 + 0.0125), {0.12, 0.085, 0.0125});  // 3
  scene.box(kTable.on_table(-0.02, 0.06, 0.055 + 0.015), {0.10, 0.07, 0.015});   // 4
  const RenderedScene rendered = scene.render();
  const FrameResult frame = run_one(rendered);
  // Every book is an object; none is taken for a table.
  const std::vector<int> majority = majority_labels(rendered.object, 4, frame.labels);
  for (int book = 2; book <= 4; ++book)
    EXPECT_NE(majority[book], 0) << "book " << book;
  EXPECT_GE(frame.objects(), 1u) << frame.json;
  EXPECT_LE(frame.objects(), 3u) << frame.json;
}

TEST(TabletopSceneModel, BoardCoveringTheTableCarriesTheObjects) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                                // 1
  kTable.box_on_table(scene, 0.0, 1.0, {0.85, 1.6, 0.005});                  // 2: board
  scene.box(kTable.on_table(-0.15, 0.05, 0.01 + 0.06), {0.05, 0.04, 0.06});  // 3
  scene.box(kTable.on_table(0.15, 0.15, 0.01 + 0.05), {0.04, 0.04, 0.05});   // 4
  const RenderedScene rendered = scene.render();
  const FrameResult frame = run_one(rendered);
  EXPECT_EQ(frame.objects(), 2u) << frame.json;
  EXPECT_EQ(found_alone(rendered, 3, 4, frame.labels), 2);
}

TEST(TabletopSceneModel, TableEdgeAndFloorInViewAreBackground) {
  SceneBuilder scene;
  scene.box(kTable.on_table(0.0, 0.3, -0.015), {0.6, 0.4, 0.015});  // 1: table top
  scene.plane(kTable.table_point - 0.72 * kTable.up, kTable.up);    // 2: floor
  kTable.box_on_table(scene, -0.15, 0.15, {0.06, 0.05, 0.08});      // 3
  kTable.box_on_table(scene, 0.15, 0.3, {0.05, 0.05, 0.10});        // 4
  const RenderedScene rendered = scene.render();
  // The table's front edge is in view: some table pixels lie below the table's top plane.
  const FrameResult frame = run_one(rendered);
  EXPECT_EQ(frame.objects(), 2u) << frame.json;
  EXPECT_EQ(found_alone(rendered, 3, 4, frame.labels), 2);
}

TEST(TabletopSceneModel, FarWallInDisparityStepsIsBackground) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                               // 1: table
  scene.plane(kTable.table_point + 2.2 * kTable.forward, -kTable.forward);  // 2: wall
  kTable.box_on_table(scene, -0.2, 0.0, {0.06, 0.05, 0.08});                // 3
  kTable.box_on_table(scene, 0.1, 0.1, {0.05, 0.05, 0.10});                 // 4
  scene.cylinder(kTable.on_table(0.25, -0.1, 0.06), 0.04, 0.06);            // 5
  const RenderedScene rendered = scene.render();
  const FrameResult frame = run_one(rendered, true);
  EXPECT_EQ(frame.objects(), 3u) << frame.json;
  EXPECT_EQ(found_alone(rendered, 3, 5, frame.labels), 3);
}

TEST(TabletopSceneModel, CansOnAFarBookAreObjectsOfTheirOwn) {
  // 2.2 m away, in the sensor's depth steps: the cans grow no surface patch (edge bands cover
  // them), so only partition.graph's bodies in front of a flat face keep them off the book.
  TabletopFrame far;
  far.table_point = {0.0, 0.0, 2.2};
  SceneBuilder scene;
  scene.plane(far.table_point, far.up);                                // 1
  far.box_on_table(scene, 0.0, 0.0, {0.13, 0.10, 0.015});              // 2: book
  scene.cylinder(far.on_table(-0.06, 0.0, 0.03 + 0.05), 0.03, 0.05);   // 3: can
  scene.cylinder(far.on_table(0.07, 0.03, 0.03 + 0.04), 0.025, 0.04);  // 4: can
  const RenderedScene rendered = scene.render();
  const FrameResult frame = run_one(rendered, true);
  EXPECT_EQ(found_alone(rendered, 2, 4, frame.labels), 3) << frame.json;
  const FrameResult off = run_one(rendered, true, {{"objects.front_body_margin_m", "0"}});
  EXPECT_LT(found_alone(rendered, 2, 4, off.labels), 3) << off.json;
}

TEST(TabletopSceneModel, NoObjectsButABook) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);
  kTable.box_on_table(scene, 0.1, 0.0, {0.11, 0.15, 0.012});
  const FrameResult frame = run_one(scene.render(), true);
  EXPECT_EQ(frame.objects(), 1u) << frame.json;
}

}  // namespace
}  // namespace facet::test
