// Bodies in front of a face (partition.graph): left-over pixels in front of a flat face of the
// object they would join are another body; pixels on or behind it are that object's.
#include "partition/graph_front_bodies.hpp"

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <opencv2/core.hpp>

#include "left_over_scene.hpp"
#include "partition/object_labels.hpp"

namespace facet::partition {
namespace {

// Object 1 has the plane z = 1.7 m as its one flat face, seen in the image box `box_px`; ids 0
// and 2 have none.
FacesOfObject one_face(const std::array<std::int32_t, 4>& box_px = {0, 0, 39, 39}) {
  FacesOfObject faces(3);
  faces[1].planes.push_back(facing_plane(1.7F));
  faces[1].box_px = box_px;
  return faces;
}

const FrontBodyRule kRule{0.015, 30, 0.003, 0.0011};

TEST(FrontBodies, PixelsInFrontOfAFlatFaceAreABodyOfTheirOwn) {
  FrontBodyBuffers buffers;
  // Columns 40-49 continue the face (on its plane), columns 50-79 stand 5 cm in front of it.
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  s.points.colRange(50, 80).setTo(cv::Scalar(0.0F, 0.0F, 1.65F));
  EXPECT_EQ(
      claim_bodies_in_front(s.objects, s.blobs, s.points, one_face(), kRule, 525.0, buffers, 2), 3);
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(50, 80) != 2), 0);
  // The pixels on the face's plane went to the face's object first, not to the new body.
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(0, 50) != 1), 0);
}

TEST(FrontBodies, PixelsOnOrBehindTheFaceAreItsObject) {
  FrontBodyBuffers buffers;
  // A side face seen past the edge of a top face lies behind the top's plane.
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  s.points.colRange(60, 80).setTo(cv::Scalar(0.0F, 0.0F, 1.8F));
  // 1 cm in front: within the margin.
  s.points.colRange(40, 50).setTo(cv::Scalar(0.0F, 0.0F, 1.69F));
  EXPECT_EQ(
      claim_bodies_in_front(s.objects, s.blobs, s.points, one_face(), kRule, 525.0, buffers, 2), 2);
  EXPECT_EQ(cv::countNonZero(s.objects != 1), 0);
}

TEST(FrontBodies, ASmallBodyIsLeftForTheFill) {
  FrontBodyBuffers buffers;
  // 5 x 5 = 25 pixels in front, fewer than the 30 a body needs.
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  s.points(cv::Rect(60, 10, 5, 5)).setTo(cv::Scalar(0.0F, 0.0F, 1.6F));
  EXPECT_EQ(
      claim_bodies_in_front(s.objects, s.blobs, s.points, one_face(), kRule, 525.0, buffers, 2), 2);
  EXPECT_EQ(cv::countNonZero(s.objects == 0), 25);
  EXPECT_EQ(buffers.gaps.size(), 25U);  // what is left, listed for the fill
  fill_blob_gaps(s.objects, s.blobs, 2);
  EXPECT_EQ(cv::countNonZero(s.objects != 1), 0);
}

TEST(FrontBodies, AnObjectWithoutFlatFacesIsLeftAlone) {
  FrontBodyBuffers buffers;
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  s.points.colRange(50, 80).setTo(cv::Scalar(0.0F, 0.0F, 1.6F));
  const cv::Mat before = s.objects.clone();
  const FacesOfObject none(3);
  EXPECT_EQ(claim_bodies_in_front(s.objects, s.blobs, s.points, none, kRule, 525.0, buffers, 2), 2);
  EXPECT_EQ(cv::countNonZero(s.objects != before), 0);
}

TEST(FrontBodies, OffLeavesEveryPixelAsItWas) {
  FrontBodyBuffers buffers;
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  s.points.colRange(50, 80).setTo(cv::Scalar(0.0F, 0.0F, 1.6F));
  const cv::Mat before = s.objects.clone();
  const FrontBodyRule off{0.0, 30, 0.003, 0.0011};
  EXPECT_EQ(claim_bodies_in_front(s.objects, s.blobs, s.points, one_face(), off, 525.0, buffers, 2),
            2);
  EXPECT_EQ(cv::countNonZero(s.objects != before), 0);
}

TEST(FrontBodies, PixelsWithoutAPointOrOutsideEveryBlobAreNotTouched) {
  FrontBodyBuffers buffers;
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  s.points.colRange(50, 80).setTo(cv::Scalar(0.0F, 0.0F, 1.6F));
  s.points.colRange(40, 50).setTo(cv::Scalar::all(std::numeric_limits<float>::quiet_NaN()));
  s.blobs.colRange(70, 80).setTo(0);
  EXPECT_EQ(
      claim_bodies_in_front(s.objects, s.blobs, s.points, one_face(), kRule, 525.0, buffers, 2), 3);
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(40, 50)), 0);  // no point: left for the fill
  EXPECT_EQ(buffers.gaps.size(), 400U);
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(50, 70) != 2), 0);
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(70, 80)), 0);
}

TEST(FrontBodies, ABodyTouchingAnotherObjectsShareJoinsThatObject) {
  FrontBodyBuffers buffers;
  // Columns 70-79 are object 2 (say a core of the body); columns 40-69 stand in front of object
  // 1's face. Those nearer object 2 are its share already; the rest touch that share.
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  s.objects.colRange(70, 80).setTo(2);
  s.points.colRange(40, 80).setTo(cv::Scalar(0.0F, 0.0F, 1.6F));
  EXPECT_EQ(
      claim_bodies_in_front(s.objects, s.blobs, s.points, one_face(), kRule, 525.0, buffers, 3), 3);
  fill_blob_gaps(s.objects, s.blobs, 3);
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(0, 40) != 1), 0);
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(40, 80) != 2), 0);
}

// A container whose only patch is its floor: object 1 is the floor, rows and columns 30-49 on
// the plane z = 1.7 m; its walls, all around it out to 20-59, stand 10 cm in front of that
// plane, in two pieces parted by a strip of columns 38-41 on the plane above and below the floor.
LeftOverScene container_scene() {
  LeftOverScene s = left_over_scene(80, 80, 0, 1.7F);
  s.objects(cv::Rect(30, 30, 20, 20)).setTo(1);
  s.points(cv::Rect(20, 20, 40, 40)).setTo(cv::Scalar(0.0F, 0.0F, 1.6F));
  s.points(cv::Rect(38, 20, 4, 40)).setTo(cv::Scalar(0.0F, 0.0F, 1.7F));
  return s;
}

FacesOfObject floor_face() {
  return one_face({30, 30, 49, 49});
}

TEST(FrontBodies, WallsAroundTheOnlyFaceStayItsObject) {
  FrontBodyBuffers buffers;
  LeftOverScene s = container_scene();
  EXPECT_EQ(
      claim_bodies_in_front(s.objects, s.blobs, s.points, floor_face(), kRule, 525.0, buffers, 2),
      2);
  EXPECT_EQ(cv::countNonZero(s.objects != 1), 0);
  EXPECT_TRUE(buffers.gaps.empty());
}

TEST(FrontBodies, WithoutKeepEnclosingTheWallsAreCutOff) {
  FrontBodyBuffers buffers;
  LeftOverScene s = container_scene();
  FrontBodyRule rule = kRule;
  rule.keep_enclosing = false;
  EXPECT_EQ(
      claim_bodies_in_front(s.objects, s.blobs, s.points, floor_face(), rule, 525.0, buffers, 2),
      4);
  EXPECT_EQ(cv::countNonZero(s.objects(cv::Rect(20, 20, 10, 40)) == 1), 0);
}

TEST(FrontBodies, WallsOnOneSideOnlyAreABody) {
  // The ring without its right half (columns 42-59 back on the floor's plane): what is left
  // stands beside the floor, not around it, like a can at the edge of a book.
  FrontBodyBuffers buffers;
  LeftOverScene s = container_scene();
  s.points(cv::Rect(42, 20, 18, 40)).setTo(cv::Scalar(0.0F, 0.0F, 1.7F));
  EXPECT_EQ(
      claim_bodies_in_front(s.objects, s.blobs, s.points, floor_face(), kRule, 525.0, buffers, 2),
      3);
  EXPECT_EQ(cv::countNonZero(s.objects(cv::Rect(20, 20, 10, 40)) != 2), 0);
}

TEST(FrontBodies, ABodyInTheMiddleOfAFaceIsCutOff) {
  // A can standing in the middle of a book: the face's box holds the body's, not the reverse.
  FrontBodyBuffers buffers;
  LeftOverScene s = left_over_scene(80, 40, 80, 1.7F);
  s.objects(cv::Rect(35, 15, 10, 10)).setTo(0);
  s.points(cv::Rect(35, 15, 10, 10)).setTo(cv::Scalar(0.0F, 0.0F, 1.6F));
  EXPECT_EQ(claim_bodies_in_front(s.objects, s.blobs, s.points, one_face({0, 0, 79, 39}), kRule,
                                  525.0, buffers, 2),
            3);
  EXPECT_EQ(cv::countNonZero(s.objects == 2), 100);
}

TEST(FrontBodies, AFarFaceIsFlatByTheRmsItsDisparityStepsGive) {
  // 3.5 mm RMS: curved at 1 m (3 mm), a flat face at 2 m (1.1 mm x 2^2 = 4.4 mm).
  EXPECT_FALSE(kRule.is_flat_face(0.0035, 1.0));
  EXPECT_TRUE(kRule.is_flat_face(0.0035, 2.0));
  EXPECT_TRUE(kRule.is_flat_face(0.0025, 0.5));
  EXPECT_FALSE(kRule.is_flat_face(0.006, 2.0));
}

// `patches` nodes with a patch, each a flat face 1 m away, then `patchless` nodes without one.
GraphNodes flat_nodes(std::size_t patches, std::size_t patchless = 0) {
  GraphNodes graph;
  graph.nodes.resize(patches + patchless);
  for (std::size_t i = 0; i < patches; ++i) {
    graph.nodes[i].segment = static_cast<std::int32_t>(i);
    graph.nodes[i].plane = facing_plane(1.0F);
    graph.nodes[i].plane_rms_m = 0.001;
  }
  return graph;
}

TEST(FrontBodies, AnObjectWithACurvedFaceHasNoFlatFaces) {
  // Nodes 0 and 1 (flat, curved) are object 1; node 2 (flat) object 2; node 3 a patchless blob.
  GraphNodes graph = flat_nodes(3, 1);
  graph.nodes[1].plane_rms_m = 0.01;
  const std::vector<std::int32_t> group{0, 0, 1, 2};
  FacesOfObject faces;
  flat_faces_of_objects(graph, BlobSegments{}, group, 4, kRule, faces);
  ASSERT_EQ(faces.size(), 4U);
  EXPECT_TRUE(faces[0].empty());
  EXPECT_TRUE(faces[1].empty());
  EXPECT_EQ(faces[2].planes.size(), 1U);
  EXPECT_TRUE(faces[3].empty());
}

TEST(FrontBodies, AnObjectsFacesAreBoxedTogether) {
  // Nodes 0 and 1 (both flat) are object 1: its box holds both of theirs.
  GraphNodes graph = flat_nodes(2);
  graph.nodes[0].box_px = {0, 0, 10, 10};
  graph.nodes[1].box_px = {5, 20, 30, 25};
  const std::vector<std::int32_t> group{0, 0};
  FacesOfObject faces;
  flat_faces_of_objects(graph, BlobSegments{}, group, 2, kRule, faces);
  ASSERT_EQ(faces.size(), 2U);
  EXPECT_EQ(faces[1].planes.size(), 2U);
  EXPECT_EQ(faces[1].box_px, (std::array<std::int32_t, 4>{0, 0, 30, 25}));
}

}  // namespace
}  // namespace facet::partition
