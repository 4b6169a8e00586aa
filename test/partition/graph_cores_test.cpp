// Unclaimed cores (partition.graph): a wide region of a blob that no patch claimed is a body of
// its own; a narrow edge band, or a region that is wide in pixels but narrow in metres, is not.
#include "partition/graph_cores.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "left_over_scene.hpp"
#include "partition/object_labels.hpp"

namespace facet::partition {
namespace {

constexpr double kFx = 525.0;

const CoreRule kRule{8.0, 0.03, 20, 0.01};

TEST(UnclaimedCores, AWideRegionFarAwayBecomesAnObject) {
  CoreBuffers buffers;
  // 40 px of unclaimed columns beside the object: a 40 x 40 square of 13 cm at 1.7 m.
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  EXPECT_EQ(claim_unclaimed_cores(s.objects, s.blobs, s.points, kFx, {}, kRule, buffers, 2), 3);
  EXPECT_EQ(s.objects.at<std::int32_t>(20, 60), 2);  // the core's middle
  fill_blob_gaps(s.objects, s.blobs, 3);
  // Every pixel is claimed, the two objects meet between the object and the core.
  EXPECT_EQ(cv::countNonZero(s.objects == 0), 0);
  EXPECT_EQ(s.objects.at<std::int32_t>(20, 78), 2);
  EXPECT_EQ(s.objects.at<std::int32_t>(20, 41), 1);
}

TEST(UnclaimedCores, AnEdgeBandJoinsItsNeighbours) {
  CoreBuffers buffers;
  // A band 12 px wide between two claimed regions: no pixel is 8 px from both.
  LeftOverScene s = left_over_scene(80, 40, 30, 1.7F);
  s.objects.colRange(42, 80).setTo(2);
  EXPECT_EQ(claim_unclaimed_cores(s.objects, s.blobs, s.points, kFx, {}, kRule, buffers, 3), 3);
  fill_blob_gaps(s.objects, s.blobs, 3);
  EXPECT_EQ(cv::countNonZero(s.objects == 3), 0);
  EXPECT_EQ(cv::countNonZero(s.objects == 0), 0);
}

TEST(UnclaimedCores, ARegionWideInPixelsButNarrowInMetresJoinsItsBody) {
  CoreBuffers buffers;
  // The same 40 x 40 square at 0.5 m is 3.8 cm across: its widest point is 1.9 cm from the
  // border, under the 3 cm a core needs (a near face with holes, not a body).
  LeftOverScene s = left_over_scene(80, 40, 40, 0.5F);
  EXPECT_EQ(claim_unclaimed_cores(s.objects, s.blobs, s.points, kFx, {}, kRule, buffers, 2), 2);
  EXPECT_EQ(cv::countNonZero(s.objects == 2), 0);
  // With the metric floor off it is a body.
  EXPECT_EQ(claim_unclaimed_cores(s.objects, s.blobs, s.points, kFx, {}, CoreRule{8.0, 0.0, 20},
                                  buffers, 2),
            3);
}

TEST(UnclaimedCores, ACoreOnThePlaneOfAFaceBesideItIsThatFace) {
  CoreBuffers buffers;
  // The claimed half is node 0, a plane z = 1.7 m facing the camera. The unclaimed half lies on
  // that plane: the rest of the face. Raised 5 cm towards the camera it is a body in front.
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  cv::Mat node_of_pixel(s.objects.size(), CV_32SC1, cv::Scalar(-1));
  node_of_pixel.colRange(0, 40).setTo(0);
  FittedPlane plane;
  plane.normal = {0.0F, 0.0F, -1.0F};
  plane.offset_m = 1.7F;
  plane.valid = true;
  const std::vector<FittedPlane> planes{plane};
  const ClaimedFaces faces{&node_of_pixel, &planes};
  EXPECT_EQ(claim_unclaimed_cores(s.objects, s.blobs, s.points, kFx, faces, kRule, buffers, 2), 2);
  s.points.colRange(40, 80).setTo(cv::Scalar(0.0F, 0.0F, 1.65F));
  EXPECT_EQ(claim_unclaimed_cores(s.objects, s.blobs, s.points, kFx, faces, kRule, buffers, 2), 3);
  // A curved neighbour (no plane) is no evidence either way: the core is a body.
  LeftOverScene t = left_over_scene(80, 40, 40, 1.7F);
  const std::vector<FittedPlane> curved{FittedPlane{}};
  EXPECT_EQ(claim_unclaimed_cores(t.objects, t.blobs, t.points, kFx,
                                  ClaimedFaces{&node_of_pixel, &curved}, kRule, buffers, 2),
            3);
}

TEST(UnclaimedCores, OffLeavesEveryPixelAsItWas) {
  CoreBuffers buffers;
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  const cv::Mat before = s.objects.clone();
  EXPECT_EQ(claim_unclaimed_cores(s.objects, s.blobs, s.points, kFx, {}, CoreRule{0.0, 0.02, 20},
                                  buffers, 2),
            2);
  EXPECT_EQ(cv::countNonZero(s.objects != before), 0);
}

TEST(UnclaimedCores, PixelsOutsideEveryBlobAreNeverCores) {
  CoreBuffers buffers;
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  s.blobs.colRange(40, 80).setTo(0);
  EXPECT_EQ(claim_unclaimed_cores(s.objects, s.blobs, s.points, kFx, {}, kRule, buffers, 2), 2);
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(40, 80)), 0);
}

}  // namespace
}  // namespace facet::partition
