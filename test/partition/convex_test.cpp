// partition.convex specifics: steps between parallel surfaces, leftover pixels, merge count.

#include <gtest/gtest.h>

#include "partition/convex_stage.hpp"
#include "test_scenes.hpp"

namespace facet::test {
namespace {

using partition::PartitionConvex;

TEST(PartitionConvex, ParallelFacesAtAStepAreNotJoined) {
  // A thin box lying on a larger one: the two tops are parallel, the junction a step.
  Tabletop t;
  t.box(0.0, 0.0, {0.10, 0.08, 0.02}).box(0.0, 0.02, {0.06, 0.04, 0.01}, 0.0, 0.04);
  const PartitionInput input = one_blob(t.builder().render());
  const LabelImage objects = run_partition<PartitionConvex>(input);
  EXPECT_EQ(objects.count, 2);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object, 0.9));
}

TEST(PartitionConvex, PixelsInNoPatchJoinTheNearestObject) {
  PartitionInput input = box_on_box();
  // Wipe a band of patch ids across both boxes; the band's pixels must still end up right.
  input.patches.labels.rowRange(200, 215).setTo(0);
  input.adjacency = contacts_of(input.patches.labels);
  const LabelImage objects = run_partition<PartitionConvex>(input);
  EXPECT_EQ(objects.count, 2);
  EXPECT_TRUE(matches_bodies(objects, input.scene.object, 0.9));
  EXPECT_EQ(cv::countNonZero(objects.labels > 0), cv::countNonZero(input.blobs.labels > 0));
}

TEST(PartitionConvex, ReportsMerges) {
  std::vector<Metric> metrics;
  const LabelImage objects = run_partition<PartitionConvex>(single_box(), {}, &metrics);
  EXPECT_EQ(objects.count, 1);
  EXPECT_GE(metric_value(metrics, "merges"), 2.0);  // three faces, two joins at least
}

}  // namespace
}  // namespace facet::test
