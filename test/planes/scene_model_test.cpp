// The scene model of planes.support and grow.blobs (docs/planes.md): the table, the structure
// around it and the objects on it, on rendered scenes with perfect patches. Flat objects (books,
// trays, a board) lying on the table are objects, never support planes; what stands on them is
// stacked, not supported by a second table; the table's front edge and what lies beyond the
// table are background.
#include "planes/scene_model.hpp"

#include <gtest/gtest.h>

#include <string>

#include "planes_test_scene.hpp"

namespace facet::test {
namespace {

const TabletopFrame kTable;

// Share of primitive `object`'s pixels that lie in some blob.
double share_in_blobs(const SceneRun& run, int object) {
  const auto total = static_cast<double>(pixels_of(run.scene.object, object));
  return 1.0 -
         static_cast<double>(count_where(run.scene.object, object, run.blobs.labels, 0)) / total;
}

std::int32_t table_planes(const SupportPlanes& planes) {
  std::int32_t n = 0;
  for (const Plane& plane : planes.planes)
    n += plane.role == PlaneRole::table ? 1 : 0;
  return n;
}

// A book 24 x 17 cm lying on the table, `thickness_m` thick, and a box beside it.
SceneBuilder book_on_table(double thickness_m) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                                 // 1: table
  kTable.box_on_table(scene, -0.12, 0.05, {0.12, 0.085, 0.5 * thickness_m});  // 2: book
  kTable.box_on_table(scene, 0.2, 0.05, {0.05, 0.04, 0.07});                  // 3: box
  return scene;
}

TEST(SceneModel, BookLyingOnTheTableIsAnObject) {
  for (const double thickness_m : {0.01, 0.02, 0.04}) {
    const SceneRun run = run_scene(book_on_table(thickness_m));
    SCOPED_TRACE("book " + std::to_string(thickness_m) + " m thick");
    ASSERT_EQ(run.planes.planes.planes.size(), 1u);
    const Plane& table = run.planes.planes.planes[0];
    EXPECT_EQ(table.role, PlaneRole::table);
    EXPECT_EQ(run.planes.planes.table_id, table.id);
    // The table plane is the table's, not the book's.
    EXPECT_NEAR(table.signed_distance_m(kTable.table_point), 0.0, 0.002);
    EXPECT_GT(share_in_blobs(run, 2), 0.9);
    EXPECT_GT(share_in_blobs(run, 3), 0.9);
    EXPECT_EQ(run.blobs.count, 2);
  }
}

// The paper's size rule would take the book for a second support; with min_object_height_m
// above the book's thickness it is part of the table's level again and lost.
TEST(SceneModel, MinObjectHeightDecidesWhatIsFlatEnough) {
  const SceneRun found = run_scene(book_on_table(0.01));
  EXPECT_GT(share_in_blobs(found, 2), 0.9);
  const SceneRun lost = run_scene(book_on_table(0.01), {{"min_object_height_m", 0.015}});
  EXPECT_LT(share_in_blobs(lost, 2), 0.1);
}

TEST(SceneModel, BoxOnABookIsStackedNotSupported) {
  SceneBuilder scene = book_on_table(0.03);
  scene.box(kTable.on_table(-0.12, 0.05, 0.03 + 0.06), {0.04, 0.04, 0.06});  // 4: on the book
  const SceneRun run = run_scene(scene);
  ASSERT_EQ(run.planes.planes.planes.size(), 1u);
  EXPECT_EQ(table_planes(run.planes.planes), 1);
  for (int object = 2; object <= 4; ++object) {
    EXPECT_GT(share_in_blobs(run, object), 0.9) << "object " << object;
  }
  // The book and the box on it touch: one blob, which the object stage splits.
  EXPECT_EQ(majority_label(run.scene.object, 2, run.blobs.labels),
            majority_label(run.scene.object, 4, run.blobs.labels));
}

TEST(SceneModel, ThreeBooksStacked) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                                   // 1
  kTable.box_on_table(scene, 0.0, 0.05, {0.14, 0.10, 0.015});                   // 2
  scene.box(kTable.on_table(0.01, 0.04, 0.03 + 0.0125), {0.12, 0.09, 0.0125});  // 3
  scene.box(kTable.on_table(-0.01, 0.05, 0.055 + 0.01), {0.10, 0.075, 0.01});   // 4
  const SceneRun run = run_scene(scene);
  ASSERT_EQ(run.planes.planes.planes.size(), 1u);
  EXPECT_NEAR(run.planes.planes.planes[0].signed_distance_m(kTable.table_point), 0.0, 0.002);
  for (int book = 2; book <= 4; ++book) {
    EXPECT_GT(share_in_blobs(run, book), 0.9) << "book " << book;
  }
}

// A board 1 cm thick covering the table as far as the camera sees, bar slivers at the sides:
// the slivers lie below the board but hold less than min_table_fraction of the view, so the
// board is the support, and what stands on it is found.
TEST(SceneModel, BoardCoveringTheTableIsTheSupport) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                               // 1
  kTable.box_on_table(scene, 0.0, 1.0, {0.85, 1.6, 0.005});                 // 2: board
  scene.box(kTable.on_table(-0.1, 0.05, 0.01 + 0.06), {0.05, 0.04, 0.06});  // 3
  scene.box(kTable.on_table(0.15, 0.15, 0.01 + 0.05), {0.04, 0.04, 0.05});  // 4
  const SceneRun run = run_scene(scene);
  const auto sliver_px = static_cast<double>(pixels_of(run.scene.object, 1));
  ASSERT_GT(sliver_px, 1000.0);
  ASSERT_LT(sliver_px, 0.05 * static_cast<double>(cv::countNonZero(run.scene.object)));
  EXPECT_EQ(run.blobs.count, 2);
  EXPECT_GT(share_in_blobs(run, 3), 0.9);
  EXPECT_GT(share_in_blobs(run, 4), 0.9);
  EXPECT_LT(share_in_blobs(run, 2), 0.05);
  ASSERT_NE(run.planes.planes.table(), nullptr);
  EXPECT_NEAR(run.planes.planes.table()->signed_distance_m(kTable.table_point), -0.01, 0.002);
}

// The same board with the table in view all around it: the board is an object lying on the
// table, and the boxes standing on it are stacked on it (one blob, for the object stage to cut).
TEST(SceneModel, BoardOnAWideTableIsAnObject) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                               // 1
  kTable.box_on_table(scene, 0.0, 0.1, {0.3, 0.25, 0.005});                 // 2: board
  scene.box(kTable.on_table(-0.1, 0.05, 0.01 + 0.06), {0.05, 0.04, 0.06});  // 3
  scene.box(kTable.on_table(0.15, 0.15, 0.01 + 0.05), {0.04, 0.04, 0.05});  // 4
  const SceneRun run = run_scene(scene);
  ASSERT_NE(run.planes.planes.table(), nullptr);
  EXPECT_NEAR(run.planes.planes.table()->signed_distance_m(kTable.table_point), 0.0, 0.002);
  EXPECT_EQ(run.blobs.count, 1);
  for (int object = 2; object <= 4; ++object) {
    EXPECT_GT(share_in_blobs(run, object), 0.9) << "object " << object;
  }
}

// Points on a grid of `side` × `side` cells of 1 cm, at (x0, z0) on the floor plan (y = 0, up -y).
std::vector<Eigen::Vector3f> grid_m(float x0_m, float z0_m, int side) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j)
      points.emplace_back(x0_m + 0.01F * static_cast<float>(i), 0.0F,
                          z0_m + 0.01F * static_cast<float>(j));
  }
  return points;
}

TEST(SceneModel, ShareOverIsThePartOfTheUpperPointsInsideTheLowerOutline) {
  const Eigen::Vector3f up(0.0F, -1.0F, 0.0F);
  const std::vector<Eigen::Vector3f> lower = grid_m(0.0F, 0.0F, 41);  // 40 cm square
  EXPECT_DOUBLE_EQ(planes::share_over(grid_m(0.1F, 0.1F, 11), lower, up), 1.0);
  EXPECT_DOUBLE_EQ(planes::share_over(grid_m(0.6F, 0.0F, 11), lower, up), 0.0);
  // 6 of the upper square's 11 columns (x 0.35-0.40 of 0.35-0.45) lie over the lower one.
  EXPECT_NEAR(planes::share_over(grid_m(0.35F, 0.1F, 11), lower, up), 6.0 / 11.0, 1e-9);
  // The height along up does not matter: seen from above.
  std::vector<Eigen::Vector3f> raised = grid_m(0.1F, 0.1F, 11);
  for (Eigen::Vector3f& p : raised)
    p += 0.05F * up;
  EXPECT_DOUBLE_EQ(planes::share_over(raised, lower, up), 1.0);
  // No outline, no share: a line, or nothing.
  EXPECT_EQ(planes::share_over(grid_m(0.1F, 0.1F, 3), grid_m(0.0F, 0.0F, 1), up), 0.0);
  EXPECT_EQ(planes::share_over({}, lower, up), 0.0);
}

// A low table with a chair's seat behind it, a centimetre lower and larger than a twentieth of
// the view: the seat is a level just below the table's, but beside the table, not under it, so
// the table stays the table. Taken for the table that the table stood on, the seat would take
// the table's role, and the table top would be an object lying on it.
TEST(SceneModel, ASeatBesideTheTableACentimetreLowerIsNotTheTable) {
  SceneBuilder scene;
  scene.box(kTable.on_table(0.0, 0.05, -0.02), {0.35, 0.3, 0.02});  // 1: table top
  scene.box(kTable.on_table(0.0, 0.7, -0.03), {0.45, 0.3, 0.02});   // 2: seat, 1 cm lower
  scene.plane(kTable.table_point - 0.45 * kTable.up, kTable.up);    // 3: floor
  kTable.box_on_table(scene, -0.15, 0.0, {0.05, 0.04, 0.07});       // 4
  kTable.box_on_table(scene, 0.15, 0.1, {0.04, 0.04, 0.05});        // 5
  const SceneRun run = run_scene(scene);
  const auto seat_px = static_cast<double>(pixels_of(run.scene.object, 2));
  ASSERT_GT(seat_px, 0.05 * static_cast<double>(cv::countNonZero(run.scene.object)));
  ASSERT_LT(seat_px, static_cast<double>(pixels_of(run.scene.object, 1)));
  ASSERT_NE(run.planes.planes.table(), nullptr);
  EXPECT_NEAR(run.planes.planes.table()->signed_distance_m(kTable.table_point), 0.0, 0.002);
  EXPECT_LT(share_in_blobs(run, 1), 0.05);
  EXPECT_LT(share_in_blobs(run, 2), 0.05);
  EXPECT_GT(share_in_blobs(run, 4), 0.9);
  EXPECT_GT(share_in_blobs(run, 5), 0.9);
  // Without the test of what lies under what, the seat is the table.
  const SceneRun beside = run_scene(scene, {{"min_table_under_share", 0.0}});
  ASSERT_NE(beside.planes.planes.table(), nullptr);
  EXPECT_NEAR(beside.planes.planes.table()->signed_distance_m(kTable.table_point), 0.01, 0.002);
  // ... and the table, a centimetre above it, an object top in a blob with what stands on it.
  EXPECT_GT(share_in_blobs(beside, 1), 0.5);
}

// A board lying on a table, larger in view than the strips of table on either side of it: the
// strips lie around the board, so the table is still the strips' level, and the board an object.
TEST(SceneModel, ABoardWiderThanTheTableInViewStillLiesOnIt) {
  SceneBuilder scene;
  scene.plane(kTable.table_point, kTable.up);                               // 1
  kTable.box_on_table(scene, 0.0, 0.5, {0.5, 1.2, 0.005});                  // 2: board
  scene.box(kTable.on_table(-0.1, 0.05, 0.01 + 0.06), {0.05, 0.04, 0.06});  // 3
  const SceneRun run = run_scene(scene);
  const auto table_px = static_cast<double>(pixels_of(run.scene.object, 1));
  ASSERT_LT(table_px, static_cast<double>(pixels_of(run.scene.object, 2)));
  ASSERT_GT(table_px, 0.05 * static_cast<double>(cv::countNonZero(run.scene.object)));
  ASSERT_NE(run.planes.planes.table(), nullptr);
  EXPECT_NEAR(run.planes.planes.table()->signed_distance_m(kTable.table_point), 0.0, 0.002);
  EXPECT_GT(share_in_blobs(run, 2), 0.9);
  EXPECT_GT(share_in_blobs(run, 3), 0.9);
}

// A table 4 cm thick seen with its front edge, the floor below and a wall behind: the edge strip
// lies below the table plane, so it is structure, not an object.
TEST(SceneModel, TableFrontEdgeIsStructure) {
  SceneBuilder scene;
  scene.box(kTable.on_table(0.0, 0.25, -0.02), {0.6, 0.4, 0.02});           // 1: table top
  scene.plane(kTable.table_point - 0.75 * kTable.up, kTable.up);            // 2: floor
  scene.plane(kTable.table_point + 1.2 * kTable.forward, -kTable.forward);  // 3: wall
  kTable.box_on_table(scene, -0.15, 0.05, {0.06, 0.05, 0.08});              // 4
  kTable.box_on_table(scene, 0.15, 0.25, {0.05, 0.05, 0.10});               // 5
  const SceneRun run = run_scene(scene);
  EXPECT_EQ(run.blobs.count, 2);
  for (int background = 1; background <= 3; ++background) {
    EXPECT_LT(share_in_blobs(run, background), 0.01) << "background " << background;
  }
  const SupportPlanes& planes = run.planes.planes;
  ASSERT_NE(planes.table(), nullptr);
  EXPECT_NEAR(planes.table()->signed_distance_m(kTable.table_point), 0.0, 0.002);
  bool floor = false;
  for (const Plane& plane : planes.planes)
    floor = floor || plane.role == PlaneRole::floor;
  EXPECT_TRUE(floor);
  // With the table tests off the edge strip comes back as a blob of its own.
  const LabelImage without =
      run_blobs(run.planes.patches, run.points, &planes, {{"on_table", false}});
  EXPECT_EQ(without.count, 3);
}

// Boxes standing on the floor beyond the table's far end (seen past it) are outside the table's
// outline; a box on the table is not.
TEST(SceneModel, ThingsBeyondTheTableAreNotObjects) {
  SceneBuilder scene;
  scene.box(kTable.on_table(0.0, 0.0, -0.02), {0.6, 0.3, 0.02});  // 1: table top
  scene.plane(kTable.table_point - 0.75 * kTable.up, kTable.up);  // 2: floor
  kTable.box_on_table(scene, 0.0, 0.0, {0.05, 0.05, 0.08});       // 3: on the table
  // 4: a box on a shelf beyond the table, raised to the table's height
  scene.box(kTable.on_table(0.1, 0.6, 0.1), {0.1, 0.05, 0.1});
  const SceneRun run = run_scene(scene);
  ASSERT_NE(run.planes.planes.table(), nullptr);
  EXPECT_FALSE(run.planes.planes.table_outline_m.empty());
  EXPECT_GT(share_in_blobs(run, 3), 0.9);
  EXPECT_LT(share_in_blobs(run, 4), 0.05);
  const LabelImage without =
      run_blobs(run.planes.patches, run.points, &run.planes.planes, {{"on_table", false}});
  EXPECT_EQ(without.count, run.blobs.count + 1);
}

}  // namespace
}  // namespace facet::test
