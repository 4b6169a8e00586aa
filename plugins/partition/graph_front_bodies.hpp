#pragma once
// Bodies in front of a face (partition.graph). An object whose faces are all flat (a box, a
// book, a tray) is convex: none of its points lies in front of the plane of one of its faces.
// Left-over pixels that would be shared out to such an object, but stand in front of one of its
// faces, belong to another body: a can on a book or a box on a box far from the camera, where
// neither grew a patch of its own and both are one blob. So do those beyond a face of a box in its
// own plane: a can beside the box.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>
#include <opencv2/core/mat.hpp>
#include <span>
#include <vector>

#include "facet/algo/connected_components.hpp"
#include "partition/graph_nodes.hpp"
#include "partition/segment_plane.hpp"

namespace facet::partition {

struct FrontBodyRule {
  double margin_m = 0.0;        // in front of a face's plane by more than this; 0 = off
  std::int32_t min_px = 30;     // smallest body that becomes an object
  double face_max_rms_m = 0.0;  // a node whose plane fits this well (RMS) is a flat face ...
  // ... or within this times (depth / 1 m)²: a flat face's disparity steps alone give it an RMS
  // that grows with the square of its depth (3.3 mm at 2 m for a Kinect).
  double face_rms_at_1m_m = 0.0;
  // Bodies of one object that together reach around its faces in the image (their box holds the
  // faces' box, short of it by a tenth at most) stand around them, not on them: the walls of an
  // open container whose only patch is its floor. They stay the object's.
  bool keep_enclosing = true;
  // A box's face spans the box in both directions of its plane, so a left-over point on no face's
  // plane (within on_plane_m) that lies beyond the extent of one of its object's planar faces
  // (RMS within face_max_rms_m), by more than beyond_margin_m plus beyond_band_px pixels at its
  // depth, is another body's too: a can beside a box, lower than its top. The band is what the
  // face's patch loses to the edges along its border. 0 = off.
  double beyond_margin_m = 0.0;
  double beyond_band_px = 6.0;
  double on_plane_m = 0.01;

  bool is_flat_face(double plane_rms_m, double depth_m) const;
};

// An image rectangle, inclusive: u_min, v_min, u_max, v_max. kNoPixels holds none, so that a
// box grown from it by each pixel or corner added is exactly their bounding box.
using PixelBox = std::array<std::int32_t, 4>;
constexpr PixelBox kNoPixels{std::numeric_limits<std::int32_t>::max(),
                             std::numeric_limits<std::int32_t>::max(), -1, -1};

// Where a flat face lies in its own plane: the range of its points' coordinates along two
// orthogonal axes of the plane, its principal directions (a rectangle's sides). The points of the
// object's other faces on that plane count too (pieces of one face an edge line broke).
struct FaceExtent {
  bool bounds = false;  // planar by face_max_rms_m: a far face's extent is not trusted
  Eigen::Vector3f origin_m = Eigen::Vector3f::Zero();
  Eigen::Vector3f axis_u = Eigen::Vector3f::UnitX();
  Eigen::Vector3f axis_v = Eigen::Vector3f::UnitY();
  float min_u_m = 0.0F;
  float max_u_m = 0.0F;
  float min_v_m = 0.0F;
  float max_v_m = 0.0F;
};

struct FlatFaces {
  std::vector<FittedPlane> planes;
  std::vector<FaceExtent> extents;  // one per plane with beyond_margin_m, else none
  std::vector<std::int32_t> nodes;  // the graph node of each plane
  PixelBox box_px = kNoPixels;      // the bounding box of the faces in the image
  bool empty() const { return planes.empty(); }
};
using FacesOfObject = std::vector<FlatFaces>;

// Per object id (index), the planes of its faces when all of them are flat; empty for an object
// with a curved face (a bowl's inside lies in front of its floor: no convex object) and for ids
// without a node. `group` gives each node's object as id - 1, as GraphCut::groups does. With
// `rule.beyond_margin_m`, each face's extent too, from its points in `points`.
void flat_faces_of_objects(const GraphNodes& graph, const BlobSegments& points,
                           std::span<const std::int32_t> group, std::int32_t id_count,
                           const FrontBodyRule& rule, FacesOfObject& faces);

// Images reused from frame to frame (one per stage instance).
struct FrontBodyBuffers {
  std::vector<std::int32_t> gaps;
  cv::Mat state;
  cv::Mat body;
  std::vector<std::int32_t> id_of_body;
  std::vector<std::int32_t> object_of_body;
  std::vector<PixelBox> box_of_bodies;  // per object id
  algo::ComponentLabeler components;
};

// `objects`, `blobs` (CV_32SC1) and `points` (CV_32FC3), all continuous. `objects` holds the
// ids placed so far; its 0 pixels inside blobs are the left-over pixels. Each left-over pixel with
// a point is given the object that fill_blob_gaps would give it (fewest steps within the blob).
// When that object has flat faces (`faces`, by id):
// - a pixel more than `margin_m` in front of one of their planes is a body's. Connected bodies
//   (8 neighbours) of at least `min_px` pixels become objects, ids from `next_id` on, or join
//   the object of their blob whose share (pixels, or left-over pixels nearest to it) they touch,
//   or stay the object's when they reach around its faces (`keep_enclosing`);
// - so is a pixel on none of their planes but beyond the extent of a planar one
//   (`beyond_margin_m`, with `beyond_band_px` converted at the pixel's depth by `fx_px`);
// - any other pixel is the object's now, so that a new body does not grow into it later.
// Pixels of smaller bodies, without a point, or nearest to an object without flat faces stay 0
// for fill_blob_gaps; on return `buffers.gaps` lists them (collect_blob_gaps' list of what is
// left), so that the fill need not search the image again. Returns the next free id.
std::int32_t claim_bodies_in_front(cv::Mat& objects, const cv::Mat& blobs, const cv::Mat& points,
                                   const FacesOfObject& faces, const FrontBodyRule& rule,
                                   double fx_px, FrontBodyBuffers& buffers, std::int32_t next_id);

}  // namespace facet::partition
