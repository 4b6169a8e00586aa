// The partition stages on degenerate and extreme input: no crash, sensible output.

#include <gtest/gtest.h>

#include "facet/error.hpp"
#include "partition/bsp_stage.hpp"
#include "partition/convex_stage.hpp"
#include "partition/graph_stage.hpp"
#include "test_scenes.hpp"

namespace facet::test {
namespace {

template <class Stage>
class PartitionRobustness : public ::testing::Test {};

using Stages = ::testing::Types<partition::PartitionBsp, partition::PartitionConvex,
                                partition::PartitionGraph>;
TYPED_TEST_SUITE(PartitionRobustness, Stages);

// Zero-size images break the image types' format, so they never reach a partition stage.
TYPED_TEST(PartitionRobustness, EmptyImagesAreRefusedBeforeTheStage) {
  const PartitionInput input;
  EXPECT_THROW(run_partition<TypeParam>(input), std::invalid_argument);
}

TYPED_TEST(PartitionRobustness, NoBlobsGiveNoObjects) {
  PartitionInput input = box_on_box();
  input.blobs.labels.setTo(0);
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 0);
  EXPECT_EQ(cv::countNonZero(objects.labels), 0);
}

TYPED_TEST(PartitionRobustness, BlobWithoutPatchesIsOneObject) {
  PartitionInput input = box_on_box();
  input.patches.labels.setTo(0);
  input.adjacency = PatchAdjacency{};
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 1);
  EXPECT_EQ(cv::countNonZero(objects.labels), cv::countNonZero(input.blobs.labels));
}

TYPED_TEST(PartitionRobustness, BlobPixelsWithoutPointsAreStillLabelled) {
  PartitionInput input = box_on_box();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  input.points.points.rowRange(150, 160).setTo(cv::Scalar(nan, nan, nan));
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 2);
  EXPECT_EQ(cv::countNonZero(objects.labels), cv::countNonZero(input.blobs.labels));
}

TYPED_TEST(PartitionRobustness, OneHugeBlobOfManyObjects) {
  // A grid of 25 boxes and cylinders filling the view, all in one blob, plus pixels nobody hit.
  Tabletop t(60.0);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      const double x = -0.24 + 0.12 * i;
      const double y = -0.2 + 0.1 * j;
      if ((i + j) % 2 == 0) {
        t.box(x, y, {0.05, 0.04, 0.03 + 0.01 * j}, 10.0 * i);
      } else {
        t.cylinder(x, y, 0.04, 0.04 + 0.01 * i);
      }
    }
  }
  PartitionInput input = one_blob(t.builder().render());
  input.blobs.labels.setTo(1);  // even the empty pixels: they have no point
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_GE(objects.count, 1);
  EXPECT_LE(objects.count, 60);
  EXPECT_EQ(cv::countNonZero(objects.labels), static_cast<int>(objects.labels.total()));
}

TYPED_TEST(PartitionRobustness, TwoHundredTinyBlobs) {
  PartitionInput input = single_box();
  cv::Mat blobs = cv::Mat::zeros(input.blobs.labels.size(), CV_32SC1);
  cv::Mat patches = cv::Mat::zeros(input.blobs.labels.size(), CV_32SC1);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  input.points.points.setTo(cv::Scalar(nan, nan, nan));
  for (int k = 0; k < 200; ++k) {
    const int u = 20 + 30 * (k % 20);
    const int v = 20 + 40 * (k / 20);
    const cv::Rect rect(u, v, 4, 4);
    blobs(rect).setTo(k + 1);
    patches(rect).setTo(k % 3 == 0 ? 0 : k + 1);
    input.points.points(rect).setTo(cv::Scalar(0.001 * u, 0.001 * v, 1.0));
  }
  input.blobs = label_image(blobs);
  input.patches = label_image(patches);
  input.adjacency = contacts_of(patches);
  const LabelImage objects = run_partition<TypeParam>(input);
  EXPECT_EQ(objects.count, 200);
}

TYPED_TEST(PartitionRobustness, MismatchedSizesAreAnError) {
  PartitionInput input = single_box();
  input.patches.labels = cv::Mat::zeros(10, 10, CV_32SC1);
  EXPECT_THROW(run_partition<TypeParam>(input), StageError);
}

}  // namespace
}  // namespace facet::test
