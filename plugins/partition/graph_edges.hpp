#pragma once
// The edges of the surface-patch graph (partition.graph): pairs of nodes that belong to one
// object, and the feature that found each pair. One file per feature: graph_edges_convex.cpp,
// graph_edges_coplanar.cpp, graph_edges_curvature.cpp, graph_edges_floor.cpp.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string_view>
#include <vector>

#include "partition/blob_segments.hpp"
#include "partition/convex_merge.hpp"
#include "partition/graph_nodes.hpp"

namespace facet::partition {

enum class EdgeFeature : std::uint8_t { convex, coplanar, curvature, floor };

std::string_view feature_name(EdgeFeature feature);

struct GraphEdge {
  std::int32_t a = 0;  // node indices, a < b
  std::int32_t b = 0;
  EdgeFeature feature = EdgeFeature::convex;
  // Touching 8-neighbour pixel pairs of the two patches in the image (0 when they do not
  // touch): how strongly the edge holds when a step pair must be separated (graph_steps.hpp).
  std::int32_t contact_px = 0;
};

// What the features read besides the gathered points: the images, for looking along the image
// between two patches.
struct FrameImages {
  const cv::Mat* patches = nullptr;  // CV_32SC1, continuous
  const cv::Mat* points = nullptr;   // CV_32FC3, continuous
  const cv::Mat* blobs = nullptr;    // CV_32SC1, continuous
};

// convex ("cutfree"): adjacent patches of one blob whose junction is convex (is_convex_junction,
// the test partition.convex uses).
void add_convex_edges(const BlobSegments& points, const GraphNodes& graph,
                      const PatchNeighbours& neighbours, const ConvexRule& rule,
                      std::vector<std::int32_t>& node_of_patch, std::vector<GraphEdge>& edges);

struct CoplanarRule {
  double max_angle_deg = 15.0;     // normals of the two planes at most this far apart
  double max_distance_m = 0.015;   // each centre at most this far from the other's plane
  double max_gap_m = 0.25;         // 3D boxes of the two patches at most this far apart
  double front_margin_m = 0.01;    // a gap pixel this much in front of the plane occludes it
  double min_front_share = 0.8;    // least share of occluding pixels among the valid gap pixels
  std::int32_t min_gap_px = 3;     // fewer valid gap pixels: no evidence, not joined
  std::int32_t lines = 3;          // image lines sampled between the two patches
  std::int32_t max_partners = 4;   // image lines only to each patch's nearest candidates
  bool across_blobs_only = false;  // only pairs of patches in different blobs
  // Touching planar patches of one blob whose centres lie at most this far from each other's
  // plane (and normals within max_angle_deg) are one surface that an edge line broke (noise, a
  // label or a seam); 0 = never joined this way.
  double touching_max_distance_m = 0.0;
  // A body of the two patches' own blob in the gap occludes too when it stands on their plane
  // (its patches, and those touching them, lie on or in front of it): a can standing on a board
  // seen in two pieces.
  bool body_on_surface = true;
};

// Per node, the nodes whose patches touch its patch in the image (grow.surfaces' adjacency),
// ascending.
using TouchingNodes = std::vector<std::vector<std::int32_t>>;
TouchingNodes touching_nodes(const GraphNodes& graph, const PatchNeighbours& neighbours);

// coplanar across an occluder: two planar patches that do not touch, on one plane, with the
// pixels between them in the image in front of that plane (graph_gap.hpp). With
// touching_max_distance_m, also two touching patches of one blob on one plane. `points` holds
// the nodes' points (body_on_surface counts a body's points behind the plane there).
void add_coplanar_edges(const BlobSegments& points, const GraphNodes& graph,
                        const FrameImages& images, const TouchingNodes& touching,
                        const CoplanarRule& rule, std::vector<GraphEdge>& edges);

struct CurvatureRule {
  double tolerance_m = 0.005;      // a point within this of the joint quadric fits it
  double min_share = 0.8;          // least share of each patch's points that fit
  double min_axis_ratio = 0.1;     // weaker curvature direction at least this of the stronger
  std::int32_t max_samples = 256;  // points per patch used for the fit
  double max_gap_m = 0.02;         // 3D boxes this close: tested without an occluder
  // 3D boxes further apart, up to this: tested only when an occluder hides the gap (the
  // coplanar feature's occlusion test, against the chord plane of the two patches).
  double max_occluded_gap_m = 0.15;
  // Where no elliptic quadric fits, one circular cylinder of at most this radius may (a can lying
  // behind an occluder, whose pieces the quadric takes for two planes); 0 = quadrics only.
  double cylinder_max_radius_m = 0.15;
  bool flat_rims = true;
};

// curvature: two curved patches close in 3D (often in two blobs: the rim of a bowl seen from
// above is a depth step between inside and outside), or further apart with an occluder between
// them, that one elliptic quadric (sphere, ellipsoid, elliptic cylinder or paraboloid: the
// shapes of cups, bowls and cans) or one circular cylinder (cylinder_fit.hpp) fits.
void add_curvature_edges(const BlobSegments& points, const GraphNodes& graph,
                         const FrameImages& images, const CoplanarRule& occlusion,
                         const CurvatureRule& rule, std::vector<GraphEdge>& edges);

struct FloorRule {
  double min_rise_m = 0.01;     // the wall's centroid at least this in front of the floor's plane
  double min_wrap_deg = 200.0;  // the wall's points wrap around the floor's centre this far
  std::int32_t max_samples = 256;  // wall points used for the wrap
};

// floor: a planar patch and a larger curved one of its blob that touch, where the curved one
// rises in front of the planar one's plane and its points, seen in that plane, turn around the
// planar one's centroid (seen at its own mean pixel) by more than half a turn: the flat floor of
// a pot, bowl or cup and the inside of its wall, which meet at a concave crease that the convex
// feature rightly refuses. The size test matters as much as the turn: seen at a slant, a cup in
// front of a box's face can turn around the face's centre in the face's plane too (mOSD
// learn42), but the face is then the larger, and a container's floor seldom is.
void add_floor_edges(const BlobSegments& points, const GraphNodes& graph, const FrameImages& images,
                     const TouchingNodes& touching, const FloorRule& rule,
                     std::vector<GraphEdge>& edges);

}  // namespace facet::partition
