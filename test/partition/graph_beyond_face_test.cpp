// Bodies beyond a face (partition.graph, front_body_beyond_margin_m): a box's face spans the box in
// both directions of its plane, so left-over pixels beyond it, on none of its object's planes, are
// another body; pixels within its extent, or on a plane of the object, are the object's.
#include <gtest/gtest.h>

#include <array>
#include <opencv2/core.hpp>

#include "left_over_scene.hpp"
#include "partition/graph_front_bodies.hpp"
#include "partition/object_labels.hpp"

namespace facet::partition {
namespace {

constexpr double kFx = 525.0;

// Points back-projected at their column: x = (u - 40) z / fx, y = 0, z = z_m.
void set_columns(cv::Mat& points, int first, int last, float z_m) {
  for (int v = 0; v < points.rows; ++v) {
    for (int u = first; u <= last; ++u) {
      points.at<cv::Vec3f>(v, u) =
          cv::Vec3f(static_cast<float>((u - 40) * static_cast<double>(z_m) / kFx), 0.0F, z_m);
    }
  }
}

// Object 1's one face: the plane z = 1.7 m over columns 0-39 (x up to -1.7 / 525 m), rows
// anywhere (its v range is wide open).
FacesOfObject box_front(bool bounds = true) {
  FacesOfObject faces(3);
  faces[1].planes.push_back(facing_plane(1.7F));
  faces[1].box_px = {0, 0, 39, 39};
  FaceExtent extent;
  extent.bounds = bounds;
  extent.origin_m = {0.0F, 0.0F, 1.7F};
  extent.min_u_m = static_cast<float>(-40 * 1.7 / kFx);
  extent.max_u_m = static_cast<float>(-1 * 1.7 / kFx);
  extent.min_v_m = -1.0F;
  extent.max_v_m = 1.0F;
  faces[1].extents.push_back(extent);
  return faces;
}

FrontBodyRule beyond_rule() {
  FrontBodyRule rule{0.015, 30, 0.003, 0.0011};
  rule.beyond_margin_m = 0.01;
  rule.beyond_band_px = 6.0;
  rule.on_plane_m = 0.01;
  return rule;
}

// The box's face in columns 0-39; what is left over beyond it, columns 40-79, stands 5 cm
// behind the face's plane (a can beside the box, its front further back).
LeftOverScene box_and_beside(float beside_z_m) {
  LeftOverScene s = left_over_scene(80, 40, 40, 1.7F);
  set_columns(s.points, 0, 39, 1.7F);
  set_columns(s.points, 40, 79, beside_z_m);
  return s;
}

// Runs the rule on `s` and expects no body: every pixel stays object 1's.
void expect_no_body(LeftOverScene s, const FacesOfObject& faces, const FrontBodyRule& rule) {
  FrontBodyBuffers buffers;
  EXPECT_EQ(claim_bodies_in_front(s.objects, s.blobs, s.points, faces, rule, kFx, buffers, 2), 2);
  EXPECT_EQ(cv::countNonZero(s.objects != 1), 0);
}

TEST(BeyondFace, PixelsBeyondAFacesExtentAreABodyOfTheirOwn) {
  FrontBodyBuffers buffers;
  LeftOverScene s = box_and_beside(1.75F);
  EXPECT_EQ(claim_bodies_in_front(s.objects, s.blobs, s.points, box_front(), beyond_rule(), kFx,
                                  buffers, 2),
            3);
  fill_blob_gaps(s.objects, s.blobs, 3, buffers.gaps);
  // The margin: 1 cm and 6 px at 1.75 m, 9 px in all beyond column 39.
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(0, 46) != 1), 0);
  EXPECT_EQ(cv::countNonZero(s.objects.colRange(50, 80) != 2), 0);
}

TEST(BeyondFace, OffItIsTheObjectsWhenNotInFront) {
  FrontBodyRule rule = beyond_rule();
  rule.beyond_margin_m = 0.0;
  expect_no_body(box_and_beside(1.75F), box_front(), rule);
}

TEST(BeyondFace, PixelsOnTheFacesPlaneAreAPieceOfTheFace) {
  // A face whose patch ended short of its corner: the rest lies on its plane.
  expect_no_body(box_and_beside(1.705F), box_front(), beyond_rule());
}

TEST(BeyondFace, OnThePlaneMeansWithinOnPlaneM) {
  // 1.5 cm behind the face's plane: off it by 1 cm, on it by 2 cm.
  FrontBodyBuffers buffers;
  LeftOverScene s = box_and_beside(1.715F);
  EXPECT_EQ(claim_bodies_in_front(s.objects, s.blobs, s.points, box_front(), beyond_rule(), kFx,
                                  buffers, 2),
            3);
  FrontBodyRule rule = beyond_rule();
  rule.on_plane_m = 0.02;
  expect_no_body(box_and_beside(1.715F), box_front(), rule);
}

TEST(BeyondFace, PixelsOnAnotherFacesPlaneAreTheObjects) {
  // The object's second face, z = 1.75 m, without an extent that bounds it: the pixels on its
  // plane beyond the first face are a piece of the second.
  FacesOfObject faces = box_front();
  faces[1].planes.push_back(facing_plane(1.75F));
  faces[1].extents.push_back(FaceExtent{});
  expect_no_body(box_and_beside(1.75F), faces, beyond_rule());
}

TEST(BeyondFace, AFaceThatIsNotPlanarBoundsNothing) {
  // A far face, flat only by the RMS its disparity steps allow, or a cylinder's side far away:
  // its patch may cover a part of it, so its extent is not the object's.
  expect_no_body(box_and_beside(1.75F), box_front(false), beyond_rule());
}

// Gathered points of three flat nodes of one object: two pieces of a face z = 1 m (x from -0.10
// to -0.02 and from 0.02 to 0.10 m, y from -0.05 to 0.05 m) and a top at right angles to it.
struct PiecesOfAFace {
  GraphNodes graph;
  BlobSegments points;
};

void add_point(BlobSegments& points, float x, float y, float z) {
  points.x.push_back(x);
  points.y.push_back(y);
  points.z.push_back(z);
  points.pixel.push_back(static_cast<std::int32_t>(points.pixel.size()));
}

PiecesOfAFace pieces_of_a_face() {
  PiecesOfAFace s;
  for (const float x0 : {-0.10F, 0.02F}) {
    Segment segment;
    segment.begin = static_cast<std::int32_t>(s.points.x.size());
    for (int i = 0; i <= 8; ++i) {
      for (int j = 0; j <= 10; ++j)
        add_point(s.points, x0 + 0.01F * static_cast<float>(i),
                  -0.05F + 0.01F * static_cast<float>(j), 1.0F);
    }
    segment.end = static_cast<std::int32_t>(s.points.x.size());
    s.points.segments.push_back(segment);
  }
  Segment top;
  top.begin = static_cast<std::int32_t>(s.points.x.size());
  for (int i = 0; i <= 20; ++i) {
    for (int j = 0; j <= 5; ++j)
      add_point(s.points, -0.10F + 0.01F * static_cast<float>(i), -0.05F,
                1.0F + 0.01F * static_cast<float>(j));
  }
  top.end = static_cast<std::int32_t>(s.points.x.size());
  s.points.segments.push_back(top);
  s.graph.nodes.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    GraphNode& node = s.graph.nodes[i];
    node.segment = static_cast<std::int32_t>(i);
    node.plane_rms_m = 0.001;
    const Segment& segment = s.points.segments[i];
    node.plane = fit_plane(s.points, segment.begin, segment.end);
  }
  return s;
}

TEST(BeyondFace, PiecesOfOneFaceShareAnExtent) {
  const PiecesOfAFace s = pieces_of_a_face();
  const std::vector<std::int32_t> group{0, 0, 0};
  FacesOfObject faces;
  flat_faces_of_objects(s.graph, s.points, group, 2, beyond_rule(), faces);
  ASSERT_EQ(faces[1].extents.size(), 3U);
  // Each piece's extent spans both pieces (0.2 m along x), not the top's depth.
  for (std::size_t f = 0; f < 2; ++f) {
    const FaceExtent& e = faces[1].extents[f];
    ASSERT_TRUE(e.bounds);
    const float width_u = e.max_u_m - e.min_u_m;
    const float width_v = e.max_v_m - e.min_v_m;
    EXPECT_NEAR(std::max(width_u, width_v), 0.20F, 1e-4F);
    EXPECT_NEAR(std::min(width_u, width_v), 0.10F, 1e-4F);
  }
  // The top's own extent: 0.2 m by 0.05 m.
  const FaceExtent& top = faces[1].extents[2];
  EXPECT_NEAR(std::max(top.max_u_m - top.min_u_m, top.max_v_m - top.min_v_m), 0.20F, 1e-4F);
  EXPECT_NEAR(std::min(top.max_u_m - top.min_u_m, top.max_v_m - top.min_v_m), 0.05F, 1e-4F);
}

TEST(BeyondFace, OnlyPlanarFacesBound) {
  PiecesOfAFace s = pieces_of_a_face();
  // Flat by the RMS a far face's disparity steps allow, not planar.
  FrontBodyRule rule = beyond_rule();
  rule.face_rms_at_1m_m = 0.005;
  s.graph.nodes[2].plane_rms_m = 0.004;
  const std::vector<std::int32_t> group{0, 0, 0};
  FacesOfObject faces;
  flat_faces_of_objects(s.graph, s.points, group, 2, rule, faces);
  ASSERT_EQ(faces[1].extents.size(), 3U);
  EXPECT_TRUE(faces[1].extents[0].bounds);
  EXPECT_FALSE(faces[1].extents[2].bounds);
}

TEST(BeyondFace, OffNoExtentsAreMade) {
  const PiecesOfAFace s = pieces_of_a_face();
  const std::vector<std::int32_t> group{0, 0, 0};
  FacesOfObject faces;
  FrontBodyRule rule = beyond_rule();
  rule.beyond_margin_m = 0.0;
  flat_faces_of_objects(s.graph, s.points, group, 2, rule, faces);
  EXPECT_EQ(faces[1].planes.size(), 3U);
  EXPECT_TRUE(faces[1].extents.empty());
}

}  // namespace
}  // namespace facet::partition
