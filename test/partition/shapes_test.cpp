// The partition stages on simple tabletop scenes where every object is in one blob.

#include <gtest/gtest.h>

#include "partition/bsp_stage.hpp"
#include "partition/convex_stage.hpp"
#include "partition/graph_stage.hpp"
#include "test_scenes.hpp"

namespace facet::test {
namespace {

template <class Stage>
class PartitionShapes : public ::testing::Test {};

using Stages = ::testing::Types<partition::PartitionBsp, partition::PartitionConvex,
                                partition::PartitionGraph>;
TYPED_TEST_SUITE(PartitionShapes, Stages);

TYPED_TEST(PartitionShapes, TwoTouchingBoxesAreTwoObjects) {
  const PartitionInput input = two_boxes_side_by_side();
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 2);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object));
}

TYPED_TEST(PartitionShapes, BoxOnBoxIsTwoObjects) {
  const PartitionInput input = box_on_box();
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 2);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object));
}

TYPED_TEST(PartitionShapes, CylinderOnBoxIsTwoObjects) {
  const PartitionInput input = cylinder_on_box();
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 2);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object));
}

TYPED_TEST(PartitionShapes, SingleBoxIsNotSplitByItsOwnFaces) {
  const PartitionInput input = single_box();
  ASSERT_GE(input.adjacency.pairs.size(), 3U);  // top and two sides visible
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 1);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object));
}

TYPED_TEST(PartitionShapes, SingleCylinderIsOneObject) {
  const PartitionInput input = single_cylinder();
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 1);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object));
}

TYPED_TEST(PartitionShapes, TallBoxBesideFlatBoxIsTwoObjects) {
  const PartitionInput input = tall_box_beside_flat_box();
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 2);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object));
}

TYPED_TEST(PartitionShapes, SeparateBlobsStaySeparate) {
  Tabletop t;
  t.box(-0.15, 0.0, {0.05, 0.05, 0.05}).cylinder(0.15, 0.0, 0.04, 0.06);
  PartitionInput input = one_blob(t.builder().render());
  input.blobs = label_image(input.scene.object);
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 2);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object));
}

TYPED_TEST(PartitionShapes, IdsFollowRasterOrderAndRepeat) {
  const PartitionInput input = box_on_box();
  const LabelImage first = run_partition<TypeParam>(input);
  const LabelImage second = run_partition<TypeParam>(input);
  EXPECT_EQ(cv::countNonZero(first.labels != second.labels), 0);
  // The first object pixel in raster order carries id 1, the next new id 2, ...
  std::int32_t next = 1;
  for (int v = 0; v < first.labels.rows; ++v) {
    for (int u = 0; u < first.labels.cols; ++u) {
      const std::int32_t id = first.labels.at<std::int32_t>(v, u);
      if (id == next) ++next;
      ASSERT_LT(id, next);
    }
  }
  EXPECT_EQ(next - 1, first.count);
}

}  // namespace
}  // namespace facet::test
