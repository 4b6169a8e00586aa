#include "partition/graph_front_bodies.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "partition/object_labels.hpp"

namespace facet::partition {
namespace {

// What claim_bodies_in_front decides for a left-over pixel.
constexpr std::uint8_t kUndecided = 0;  // left for fill_blob_gaps
constexpr std::uint8_t kInFront = 1;    // a body's, if its body is large enough
constexpr std::uint8_t kKept = 2;       // the object's it is nearest to

// Two faces of one object on one plane (pieces of a face an edge line broke) share an extent.
constexpr double kSamePlaneMinCosine = 0.966;  // 15°
constexpr double kSamePlaneMaxDistanceM = 0.01;

bool on_one_plane(const FittedPlane& a, const FittedPlane& b) {
  return normal_cosine(a, b) >= kSamePlaneMinCosine &&
         centroid_offset_m(a, b) <= kSamePlaneMaxDistanceM;
}

// A point's coordinates along the extent's axes.
Eigen::Vector2f in_plane(const FaceExtent& extent, const Eigen::Vector3f& point_m) {
  const Eigen::Vector3f d = point_m - extent.origin_m;
  return {d.dot(extent.axis_u), d.dot(extent.axis_v)};
}

// Grows `extent` to hold `point_m`.
void include(FaceExtent& extent, const Eigen::Vector3f& point_m) {
  const Eigen::Vector2f uv = in_plane(extent, point_m);
  extent.min_u_m = std::min(extent.min_u_m, uv.x());
  extent.max_u_m = std::max(extent.max_u_m, uv.x());
  extent.min_v_m = std::min(extent.min_v_m, uv.y());
  extent.max_v_m = std::max(extent.max_v_m, uv.y());
}

// A face's own extent: its points' range along its plane's axes.
FaceExtent extent_of(const BlobSegments& points, const Segment& segment, const FittedPlane& plane) {
  FaceExtent extent;
  extent.origin_m = plane.centroid_m;
  extent.axis_u = plane.axis_u;
  extent.axis_v = plane.axis_v;
  for (std::int32_t k = segment.begin; k < segment.end; ++k) {
    const auto i = static_cast<std::size_t>(k);
    include(extent, Eigen::Vector3f(points.x[i], points.y[i], points.z[i]));
  }
  return extent;
}

// Grows `extent` to hold the corners of `piece`'s rectangle: the piece seen in its plane.
void include_corners(const FaceExtent& piece, FaceExtent& extent) {
  for (const float u : {piece.min_u_m, piece.max_u_m}) {
    for (const float v : {piece.min_v_m, piece.max_v_m})
      include(extent, piece.origin_m + u * piece.axis_u + v * piece.axis_v);
  }
}

bool outside(const FaceExtent& extent, const Eigen::Vector3f& point_m, float margin_m) {
  const Eigen::Vector2f uv = in_plane(extent, point_m);
  return uv.x() < extent.min_u_m - margin_m || uv.x() > extent.max_u_m + margin_m ||
         uv.y() < extent.min_v_m - margin_m || uv.y() > extent.max_v_m + margin_m;
}

// Whether a left-over point with object `faces` is another body's: more than margin_m in front
// of one of the faces' planes, or (with beyond_margin_m) on none of them (within on_plane_m) and
// beyond the extent of a face that bounds the object. A point on a face's plane may be a piece of
// that face its patch did not reach: a real face's patch often ends short of its corners. One
// pass over the planes answers both.
bool another_bodys(const FlatFaces& faces, const cv::Vec3f& point, const FrontBodyRule& rule,
                   double fx_px) {
  const auto on_plane_m = static_cast<float>(rule.on_plane_m);
  bool on_a_face = false;
  for (const FittedPlane& face : faces.planes) {
    const float distance_m = face.signed_distance_m(point[0], point[1], point[2]);
    if (distance_m > rule.margin_m) return true;
    on_a_face = on_a_face || std::abs(distance_m) <= on_plane_m;
  }
  if (on_a_face || rule.beyond_margin_m <= 0.0 || faces.extents.empty()) return false;
  const auto margin_m =
      static_cast<float>(rule.beyond_margin_m + rule.beyond_band_px * point[2] / fx_px);
  const Eigen::Vector3f p(point[0], point[1], point[2]);
  return std::any_of(faces.extents.begin(), faces.extents.end(), [&](const FaceExtent& extent) {
    return extent.bounds && outside(extent, p, margin_m);
  });
}

// Whether `outer` reaches as far as `inner` on all four sides, short of it by a tenth of
// `inner`'s size at most: where a container's wall meets its rim, the wall lies within the
// margin of the floor's plane, and its last rows are not in front of it.
bool reaches_around(const PixelBox& outer, const PixelBox& inner) {
  const std::int32_t slack_u = (inner[2] - inner[0]) / 10;
  const std::int32_t slack_v = (inner[3] - inner[1]) / 10;
  return outer[0] <= inner[0] + slack_u && outer[1] <= inner[1] + slack_v &&
         outer[2] >= inner[2] - slack_u && outer[3] >= inner[3] - slack_v;
}

void extend(PixelBox& box, std::int32_t u, std::int32_t v) {
  box = {std::min(box[0], u), std::min(box[1], v), std::max(box[2], u), std::max(box[3], v)};
}

}  // namespace

bool FrontBodyRule::is_flat_face(double plane_rms_m, double depth_m) const {
  return plane_rms_m <= std::max(face_max_rms_m, face_rms_at_1m_m * depth_m * depth_m);
}

void flat_faces_of_objects(const GraphNodes& graph, const BlobSegments& points,
                           std::span<const std::int32_t> group, std::int32_t id_count,
                           const FrontBodyRule& rule, FacesOfObject& faces) {
  const auto ids = static_cast<std::size_t>(std::max(id_count, 0));
  faces.resize(ids);
  for (FlatFaces& object : faces)
    object = FlatFaces{};
  std::vector<bool> curved(ids, false);
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const GraphNode& node = graph.nodes[i];
    const auto id = static_cast<std::size_t>(1 + group[i]);
    if (node.segment < 0 || id >= ids) continue;  // a patchless blob has no face
    if (node.plane.valid && rule.is_flat_face(node.plane_rms_m, node.plane.centroid_m.z())) {
      FlatFaces& object = faces[id];
      extend(object.box_px, node.box_px[0], node.box_px[1]);
      extend(object.box_px, node.box_px[2], node.box_px[3]);
      object.planes.push_back(node.plane);
      object.nodes.push_back(static_cast<std::int32_t>(i));
    } else {
      curved[id] = true;
    }
  }
  for (std::size_t id = 0; id < ids; ++id) {
    if (curved[id]) faces[id] = FlatFaces{};
  }
  if (rule.beyond_margin_m <= 0.0) return;
  // Each face's extent holds its object's faces on its plane too, by the corners of their own
  // extents: pieces of one face that an edge line broke.
  std::vector<FaceExtent> own;
  for (FlatFaces& object : faces) {
    own.clear();
    for (const std::int32_t n : object.nodes) {
      const GraphNode& node = graph.nodes[static_cast<std::size_t>(n)];
      FaceExtent extent =
          extent_of(points, points.segments[static_cast<std::size_t>(node.segment)], node.plane);
      extent.bounds = node.plane_rms_m <= rule.face_max_rms_m;
      own.push_back(extent);
    }
    object.extents = own;
    for (std::size_t f = 0; f < own.size(); ++f) {
      if (!own[f].bounds) continue;
      for (std::size_t g = 0; g < own.size(); ++g) {
        if (g != f && on_one_plane(object.planes[f], object.planes[g]))
          include_corners(own[g], object.extents[f]);
      }
    }
  }
}

std::int32_t claim_bodies_in_front(cv::Mat& objects, const cv::Mat& blobs, const cv::Mat& points,
                                   const FacesOfObject& faces, const FrontBodyRule& rule,
                                   double fx_px, FrontBodyBuffers& buffers, std::int32_t next_id) {
  // The work is on the left-over pixels only, a few per cent of the image, and on the rectangle
  // around them for the bodies' labelling.
  std::vector<std::int32_t>& gaps = buffers.gaps;
  collect_blob_gaps(objects, blobs, gaps);
  if (rule.margin_m <= 0.0 || gaps.empty()) return next_id;
  const int width = objects.cols;
  cv::Point low(width, objects.rows);
  cv::Point high(0, 0);
  for (const std::int32_t i : gaps) {
    low.x = std::min(low.x, i % width);
    high.x = std::max(high.x, i % width);
  }
  low.y = gaps.front() / width;
  high.y = gaps.back() / width;
  const cv::Rect roi(low, high + cv::Point(1, 1));

  // Filled in place, `objects` shows the object each left-over pixel is nearest to, until the
  // end, where the pixels that are not decided here are 0 again.
  fill_blob_gaps(objects, blobs, next_id, gaps);
  auto* nearest = objects.ptr<std::int32_t>();
  const auto* point = points.ptr<cv::Vec3f>();
  buffers.state.create(objects.size(), CV_8UC1);
  buffers.state(roi).setTo(kUndecided);
  auto* state = buffers.state.ptr<std::uint8_t>();
  bool any_in_front = false;
  for (const std::int32_t i : gaps) {
    if (!std::isfinite(point[i][2])) continue;
    const auto id = static_cast<std::size_t>(nearest[i]);
    if (id >= faces.size() || faces[id].empty()) continue;
    if (another_bodys(faces[id], point[i], rule, fx_px)) {
      state[i] = kInFront;
      any_in_front = true;
    } else {
      state[i] = kKept;
    }
  }
  std::int32_t count = 0;
  if (any_in_front) {
    buffers.body.create(objects.size(), CV_32SC1);
    cv::Mat body_roi = buffers.body(roi);
    count = buffers.components.label(buffers.state(roi), kInFront, 8, rule.min_px, body_roi).count;
  }
  const auto* body = buffers.body.ptr<std::int32_t>();
  const auto* blob = blobs.ptr<std::int32_t>();

  // A body that touches the share of another object of its blob (that object's pixels, or the
  // left-over pixels nearest to it) is the rest of that object, e.g. of a core the same body
  // made: it joins that object, the first one met in raster order. (Within one blob every share
  // belongs to an object that has pixels already, so no id is taken twice.) Any other body is an
  // object of its own.
  std::vector<std::int32_t>& id_of = buffers.id_of_body;
  id_of.assign(static_cast<std::size_t>(count) + 1, 0);
  for (const std::int32_t i : gaps) {
    if (state[i] != kInFront || body[i] == 0) continue;
    std::int32_t& id = id_of[static_cast<std::size_t>(body[i])];
    const int u = i % width;
    const int v = i / width;
    for (int nv = std::max(v - 1, 0); nv <= std::min(v + 1, objects.rows - 1) && id == 0; ++nv) {
      for (int nu = std::max(u - 1, 0); nu <= std::min(u + 1, width - 1); ++nu) {
        const std::int32_t j = nv * width + nu;
        if (blob[j] == blob[i] && nearest[j] != nearest[i]) {
          id = nearest[j];
          break;
        }
      }
    }
  }
  // The bodies cut from one object that together reach around its faces are its walls (a
  // container's, seen as a ring or in pieces), not bodies standing on it: they stay its own.
  constexpr std::int32_t kAroundItsObject = -1;
  if (rule.keep_enclosing && count > 0) {
    std::vector<PixelBox>& box = buffers.box_of_bodies;
    std::vector<std::int32_t>& object_of = buffers.object_of_body;
    box.assign(faces.size(), kNoPixels);
    object_of.assign(id_of.size(), 0);
    for (const std::int32_t i : gaps) {
      if (state[i] != kInFront || body[i] == 0) continue;
      const auto c = static_cast<std::size_t>(body[i]);
      if (id_of[c] != 0) continue;  // joins another object's share
      if (object_of[c] == 0) object_of[c] = nearest[i];
      extend(box[static_cast<std::size_t>(nearest[i])], i % width, i / width);
    }
    for (std::size_t c = 1; c < id_of.size(); ++c) {
      const auto object = static_cast<std::size_t>(object_of[c]);
      if (id_of[c] == 0 && reaches_around(box[object], faces[object].box_px))
        id_of[c] = kAroundItsObject;
    }
  }
  for (std::size_t c = 1; c < id_of.size(); ++c) {
    if (id_of[c] == 0) id_of[c] = next_id++;
  }
  // Undo the sharing out where nothing was decided, and keep those pixels as the gaps left.
  std::size_t left = 0;
  for (const std::int32_t i : gaps) {
    if (state[i] == kKept) continue;
    const bool body_pixel = state[i] == kInFront && body[i] != 0;
    if (body_pixel && id_of[static_cast<std::size_t>(body[i])] == kAroundItsObject) continue;
    nearest[i] = body_pixel ? id_of[static_cast<std::size_t>(body[i])] : 0;
    if (!body_pixel) gaps[left++] = i;
  }
  gaps.resize(left);
  return next_id;
}

}  // namespace facet::partition
