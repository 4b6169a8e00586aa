#pragma once
// Bodies in front of a face (partition.graph). An object whose faces are all flat (a box, a
// book, a tray) is convex: none of its points lies in front of the plane of one of its faces.
// Left-over pixels that would be shared out to such an object, but stand in front of one of its
// faces, belong to another body: a can on a book or a box on a box far from the camera, where
// neither grew a patch of its own and both are one blob.

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

  bool is_flat_face(double plane_rms_m, double depth_m) const;
};

// Per object id (index), the planes of its faces when all of them are flat; empty for an object
// with a curved face (a bowl's inside lies in front of its floor: no convex object) and for ids
// without a node. `group` gives each node's object as id - 1, as GraphCut::groups does.
// An image rectangle, inclusive: u_min, v_min, u_max, v_max. kNoPixels holds none, so that a
// box grown from it by each pixel or corner added is exactly their bounding box.
using PixelBox = std::array<std::int32_t, 4>;
constexpr PixelBox kNoPixels{std::numeric_limits<std::int32_t>::max(),
                             std::numeric_limits<std::int32_t>::max(), -1, -1};

struct FlatFaces {
  std::vector<FittedPlane> planes;
  PixelBox box_px = kNoPixels;  // the bounding box of the faces in the image
  bool empty() const { return planes.empty(); }
};
using FacesOfObject = std::vector<FlatFaces>;
void flat_faces_of_objects(const GraphNodes& graph, std::span<const std::int32_t> group,
                           std::int32_t id_count, const FrontBodyRule& rule, FacesOfObject& faces);

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
// - any other pixel is the object's now, so that a new body does not grow into it later.
// Pixels of smaller bodies, without a point, or nearest to an object without flat faces stay 0
// for fill_blob_gaps; on return `buffers.gaps` lists them (collect_blob_gaps' list of what is
// left), so that the fill need not search the image again. Returns the next free id.
std::int32_t claim_bodies_in_front(cv::Mat& objects, const cv::Mat& blobs, const cv::Mat& points,
                                   const FacesOfObject& faces, const FrontBodyRule& rule,
                                   FrontBodyBuffers& buffers, std::int32_t next_id);

}  // namespace facet::partition
