// partition.bsp specifics: the keep_patches fix, the face gate and the split count.

#include <gtest/gtest.h>

#include "partition/bsp_stage.hpp"
#include "test_scenes.hpp"

namespace facet::test {
namespace {

using partition::PartitionBsp;

TEST(PartitionBsp, CuttingPatchesSplitsTheTallBoxKeepingThemDoesNot) {
  // Paper Fig. 9 right: the flat box's top plane is tried first and runs through the tall box.
  const PartitionInput input = tall_box_beside_flat_box();
  const LabelImage cut = run_partition<PartitionBsp>(input, {{"keep_patches", false}});
  const LabelImage kept = run_partition<PartitionBsp>(input, {{"keep_patches", true}});
  // Cut: the tall box's lower part stays with the flat box.
  EXPECT_FALSE(matches_bodies(cut, input.scene.object, 0.9));
  EXPECT_EQ(kept.count, 2);
  EXPECT_TRUE(matches_bodies(kept, input.scene.object));
}

TEST(PartitionBsp, ReportsSplits) {
  std::vector<Metric> metrics;
  const LabelImage objects = run_partition<PartitionBsp>(box_on_box(), {}, &metrics);
  EXPECT_EQ(metric_value(metrics, "objects"), objects.count);
  EXPECT_EQ(metric_value(metrics, "splits"), 1.0);
}

TEST(PartitionBsp, BlobWithTooFewFacePointsIsNotSplit) {
  // Faces larger than any patch here: the blob has no face and stays one object.
  const LabelImage objects =
      run_partition<PartitionBsp>(box_on_box(), {{"min_face_px", std::int64_t{1000000}}});
  EXPECT_EQ(objects.count, 1);
}

TEST(PartitionBsp, FaceRatioGateKeepsEdgeDominatedBlobsWhole) {
  PartitionInput input = box_on_box();
  // Keep only a thin stripe of each patch: most blob points are then in no patch.
  cv::Mat thin = cv::Mat::zeros(input.patches.labels.size(), CV_32SC1);
  for (int v = 0; v < thin.rows; v += 8)
    input.patches.labels.row(v).copyTo(thin.row(v));
  input.patches.labels = thin;
  EXPECT_EQ(run_partition<PartitionBsp>(input, {{"min_face_ratio", 0.5}}).count, 1);
}

}  // namespace
}  // namespace facet::test
