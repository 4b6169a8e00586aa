#include "partition/graph_stage.hpp"

#include <utility>

#include "facet/algo/pixel_scale.hpp"
#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "partition/object_labels.hpp"
#include "partition/partition_ports.hpp"
#include "partition/patch_graph.hpp"

namespace facet::partition {
namespace {

const In<PatchAdjacency> kAdjacency{"adjacency", "Which patches touch (from grow.surfaces)."};
const Out<PatchGraph> kGraph{"graph",
                             "The graph for a person to look at (nodes, edges and the feature of "
                             "each, object of each node), e.g. for io.patch_graph; only with "
                             "emit_graph, else empty."};
const Param<int> kMinPatchPx{
    "min_patch_px",
    100,
    "Smaller patches have no reliable plane; they join an object as leftover pixels. "
    "A pixel count at reference_area_px: it scales with the image area.",
    {.unit = "px", .min = 3.0, .max = 1.0e7, .origin = "grow.surfaces' min_size_px"}};
const Param<double> kPlanarMaxRmsM{
    "planar_max_rms_m",
    0.003,
    "A patch whose points are within this RMS distance of its plane is planar (the "
    "coplanar feature), else curved (the curvature feature). About twice the depth "
    "noise of a Kinect at 1 m after filter.median.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "measured on mOSD learn frames"}};
const Param<bool> kConvex{"convex",
                          true,
                          "Join adjacent patches at convex junctions.",
                          {.origin = "authors' later code (cutfree)"}};
const Param<double> kConvexToleranceM{
    "convex_tolerance_m",
    0.01,
    "Points closer than this to the other patch's plane count as behind it. Also the "
    "tolerance of 'on a face's plane' for unclaimed_core_radius_px and "
    "front_body_beyond_margin_m.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "partition.convex"}};
const Param<double> kConvexMinBehindShare{
    "convex_min_behind_share",
    0.9,
    "Least share of each patch's points not in front of the other's plane.",
    {.min = 0.0, .max = 1.0, .origin = "partition.convex"}};
const Param<double> kConvexMinAngleDeg{
    "convex_min_angle_deg",
    30.0,
    "Patches whose normals differ by less meet at a step, never a convex edge.",
    {.unit = "deg", .min = 0.0, .max = 180.0, .origin = "authors' later code (30 deg)"}};
const Param<bool> kCoplanar{
    "coplanar",
    true,
    "Join two planar patches on one plane whose gap in the image an occluder hides.",
    {.origin = "authors' later code (coplanarity)"}};
const Param<double> kCoplanarMaxAngleDeg{
    "coplanar_max_angle_deg",
    15.0,
    "Most angle between the two patches' normals.",
    {.unit = "deg", .min = 0.0, .max = 90.0, .origin = "measured on mOSD learn frames"}};
const Param<double> kCoplanarMaxDistanceM{
    "coplanar_max_distance_m",
    0.015,
    "Most distance of each patch's centre from the other's plane.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "measured on mOSD learn frames"}};
const Param<double> kCoplanarMaxGapM{
    "coplanar_max_gap_m",
    0.25,
    "Most distance between the patches' 3D bounding boxes: the widest occluder.",
    {.unit = "m", .min = 0.0, .max = 100.0, .origin = "table-top objects"}};
const Param<double> kCoplanarFrontMarginM{
    "coplanar_front_margin_m",
    0.01,
    "A gap pixel occludes the plane when its point is more than this in front of it.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "grow.blobs' Delta_blob (10 mm)"}};
const Param<double> kCoplanarMinFrontShare{
    "coplanar_min_front_share",
    0.8,
    "Least share of the gap pixels with a point that occlude the plane.",
    {.min = 0.0, .max = 1.0, .origin = "measured on mOSD learn frames"}};
const Param<int> kCoplanarMinGapPx{
    "coplanar_min_gap_px",
    3,
    "Fewer gap pixels with a point are no evidence of an occluder: not joined.",
    {.unit = "px", .min = 0.0, .max = 1.0e6}};
const Param<int> kCoplanarLines{
    "coplanar_lines",
    3,
    "Image lines sampled between two patches (through their mean pixels and beside).",
    {.min = 1.0, .max = 64.0}};
const Param<bool> kCoplanarAcrossBlobsOnly{
    "coplanar_across_blobs_only",
    false,
    "Only pairs of patches in different blobs. Off: two pieces of one blob are joined "
    "too (a box's front seen on both sides of a box in front of it, its top above "
    "joining the pieces into one blob); an occluder must be of another blob either "
    "way.",
    {.origin = "measured on mOSD learn frames: off 0.976, on 0.974 (whole objects)"}};
const Param<bool> kCoplanarBodyOnSurface{
    "coplanar_body_on_surface",
    true,
    "A body of the two patches' own blob in the gap occludes too when it stands on their "
    "plane: its patches in the gap, and the patches touching those (but for the two pieces), "
    "each have at most a fifth of their pixels more than coplanar_front_margin_m behind the "
    "plane. A can standing on a board or a book hides a band of it and touches both pieces; a "
    "taller box between two equal boxes has a face that reaches down below their tops and keeps "
    "them apart. A body without a patch gives no evidence. Off: only bodies of other blobs "
    "occlude.",
    {.origin = "measured on the generated sets: 6 of 240 frames change, all up (on_flat "
               "0.883 / 0.898 -> 0.905 / 0.912 on the checking / holdout seeds); mOSD labels "
               "byte-identical (docs/evaluation.md)"}};
const Param<double> kCoplanarTouchingMaxDistanceM{
    "coplanar_touching_max_distance_m",
    0.0,
    "Two touching planar patches of one blob with normals within "
    "coplanar_max_angle_deg and each centre at most this far from the other's plane "
    "are taken for one surface broken by an edge line (noise, a printed label, a seam) "
    "and joined. A step between two parallel faces (a magazine on a book) is higher. "
    "Two boxes standing flush side by side look the same, so the stage leaves it off; "
    "the shipped tabletop graphs set 0.005. "
    "0 = never.",
    {.unit = "m",
     .min = 0.0,
     .max = 0.1,
     .origin = "measured: 0.005 gains 0.003 F on mOSD and 0.002 on generated scenes but "
               "joins flush boxes (docs/evaluation.md)"}};
const Param<int> kMaxPartners{
    "max_partners",
    4,
    "The image lines (coplanar, and curvature beyond curvature_max_gap_m) and quadric "
    "fits are made only for each patch's nearest candidates (by 3D gap), so that the "
    "cost grows with the number of patches, not its square.",
    {.min = 1.0, .max = 1.0e6}};
const Param<bool> kCurvature{
    "curvature",
    true,
    "Join two curved patches, close or with an occluder between, that one elliptic "
    "quadric fits.",
    {.origin = "own design, after the authors' curvature feature"}};
const Param<double> kCurvatureToleranceM{
    "curvature_tolerance_m",
    0.005,
    "A point within this (first-order distance) of the joint quadric fits it; covers "
    "the wall of a cup or bowl between its inside and outside.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "measured on mOSD learn frames"}};
const Param<double> kCurvatureMinShare{
    "curvature_min_share",
    0.8,
    "Least share of each patch's points that fit.",
    {.min = 0.0, .max = 1.0, .origin = "measured on mOSD learn frames"}};
const Param<double> kCurvatureMinAxisRatio{
    "curvature_min_axis_ratio",
    0.1,
    "The quadric's weaker bending direction must be at least this share of the "
    "stronger (elliptic, not two planes).",
    {.min = 0.0, .max = 1.0}};
const Param<int> kCurvatureSamples{"curvature_samples",
                                   256,
                                   "Points per patch used for the quadric fit.",
                                   {.min = 10.0, .max = 1.0e6}};
const Param<double> kCurvatureMaxGapM{
    "curvature_max_gap_m",
    0.02,
    "Curved patches whose 3D boxes are this close are tested as they are (the inside "
    "and outside of a bowl are often two blobs, split by the depth step at the rim).",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "about twice grow.blobs' 10 mm"}};
const Param<double> kCurvatureMaxOccludedGapM{
    "curvature_max_occluded_gap_m",
    0.15,
    "Curved patches further apart, up to this, are tested only when the coplanar "
    "feature's occlusion test (its margin, share and lines, against the chord plane "
    "of the two) says an occluder hides the gap: one can seen on both sides of a "
    "bottle.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "table-top objects"}};
const Param<double> kCurvatureCylinderMaxRadiusM{
    "curvature_cylinder_max_radius_m",
    0.15,
    "Where no elliptic quadric fits two curved patches, one circular cylinder up to this "
    "radius may: its axis perpendicular to both patches' normals, curvature_min_share of "
    "each patch's points within curvature_tolerance_m of it. A can lying behind an "
    "occluder shows two pieces a few centimetres deep each, which the quadric fit takes "
    "for two planes facing the camera. 0 = quadrics only.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "table-top cylinders; measured on mOSD learn frames and generated scenes "
               "(docs/partition.md)"}};
const Param<bool> kCurvatureFlatRims{
    "curvature_flat_rims",
    true,
    "Also test a curved patch with each smaller planar patch of another blob within "
    "curvature_max_gap_m, against closed quadrics only (ellipsoid, sphere): seen from above, "
    "a bowl's outside may be a band below the rim flat enough to count as planar, while a "
    "can and the face of a box beside it fit an elliptic cylinder.",
    {.origin = "measured on mOSD learn frames and generated scenes (docs/partition.md)"}};
const Param<bool> kFloor{
    "floor",
    true,
    "Join a planar patch to a larger curved one of its blob that touches it, rises in "
    "front of its plane and turns around its centre (seen at its own mean pixel) by "
    "floor_min_wrap_deg in its plane: the flat floor of a pot, bowl or cup and the inside "
    "of its wall, which meet at a concave crease. A can before a box's face can turn "
    "around the face's centre at a slant too, but the face is then the larger; a shallow "
    "container whose floor is larger than its wall (a tray) is not joined this way.",
    {.origin = "own design; mOSD learn34-38 (pots and bowls whose floor was an object)"}};
const Param<double> kFloorMinRiseM{
    "floor_min_rise_m",
    0.01,
    "The wall's centroid lies at least this in front of the floor's plane.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "the noise of a plane at 1-2 m"}};
const Param<double> kFloorMinWrapDeg{
    "floor_min_wrap_deg",
    200.0,
    "Least turn (degrees) of the wall's points around the floor's centroid, seen in the "
    "floor's plane: a full turn less the widest empty angle.",
    {.unit = "deg",
     .min = 0.0,
     .max = 360.0,
     .origin = "180-200 alike on mOSD and the generated sets; 220 loses mOSD floors, "
               "160 joins objects of a generated pile (docs/evaluation.md)"}};
const Param<bool> kCut{"cut",
                       true,
                       "Cut weak bridges between densely joined groups.",
                       {.origin = "authors' later code"}};
const Param<double> kMaxCutCost{
    "max_cut_cost",
    0.5,
    "A group is split while its minimum cut costs less; an edge (i, j) costs "
    "1/2 (1/deg_i + 1/deg_j).",
    {.min = 0.0, .max = 1.0e6, .origin = "authors' later code (0.5)"}};
const Param<bool> kCutNeedsCycles{
    "cut_needs_cycles",
    true,
    "Cut only between dense groups: each side must hold a cycle (e.g. the three "
    "mutually convex faces of a box). The degree cost alone cuts every bridge of a "
    "tree between nodes of two or more neighbours, e.g. a box's top joined to both "
    "pieces of its occluded front.",
    {.origin = "measured on mOSD learn frames (the one cut the plain rule made there "
               "split an occluded box)"}};
const Param<int> kMaxCutNodes{
    "max_cut_nodes",
    120,
    "Groups of more nodes are not cut (the cut is cubic in the group's size).",
    {.min = 4.0, .max = 1.0e5}};
const Param<double> kUnclaimedCoreRadiusPx{
    "unclaimed_core_radius_px",
    8.0,
    "Blob pixels that no node of the graph claimed and that lie at least this many "
    "pixels from every claimed pixel and from the blob's border form cores; a core of "
    "at least unclaimed_core_min_px pixels and unclaimed_core_radius_m wide becomes an "
    "object of its own before the left-over pixels are shared out. An edge band between "
    "two faces of one body is about 5 px wide on each side and has no core; a body "
    "with no patch of its own (a box on a box, a cup on a tray, a can behind a box, far "
    "from the camera) does. A core whose points lie mostly within convex_tolerance_m of "
    "the plane of a planar patch beside it is the rest of that face and stays with it. "
    "0 = off: every unclaimed pixel joins the nearest object of its blob. A width at "
    "reference_area_px: it scales with the square root of the image area.",
    {.unit = "px",
     .min = 0.0,
     .max = 1000.0,
     .origin = "swept 7-10 on generated sets (plateau); docs/partition.md"}};
const Param<int> kUnclaimedCoreMinPx{
    "unclaimed_core_min_px",
    20,
    "Smallest core (pixels) that becomes an object. A pixel count at reference_area_px: it "
    "scales with the image area.",
    {.unit = "px", .min = 1.0, .max = 1.0e7, .origin = "20-40 alike on generated sets"}};
const Param<double> kUnclaimedCoreRadiusM{
    "unclaimed_core_radius_m",
    0.03,
    "A core must also be this wide from its widest point to the region's border in 3D "
    "(pixels x depth / fx): near the camera a face that holes kept from becoming a "
    "patch is wide in pixels but narrow in metres, and stays with its body.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "0.02-0.03 alike on generated sets; 0 splits a hole-riddled side face "
               "off mOSD learn27"}};
const Param<double> kFrontBodyMarginM{
    "front_body_margin_m",
    0.0,
    "Left-over pixels (in no patch) that would join an object whose faces are all flat, "
    "but lie more than this in front of the plane of one of its faces, belong to another "
    "body: such an object is convex. Connected, at least front_body_min_px of them become "
    "an object of their own (a can on a book, a box on a box, far from the camera where "
    "neither grew a patch), or join the object of their blob whose share they touch (a "
    "core of the same body). The object's other left-over pixels are given to it first, "
    "so that the new body does not grow into them. Objects with a curved face are left "
    "alone (a bowl's inside lies in front of its floor). An object of flat faces that "
    "is not convex (a shelf, an open box) would be cut, so the stage leaves it off; the "
    "shipped tabletop graphs set 0.015. 0 = off.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "swept 0.01-0.02 on generated sets (plateau); docs/evaluation.md"}};
const Param<int> kFrontBodyMinPx{
    "front_body_min_px",
    30,
    "Smallest body in front of a face (pixels) that becomes an object; smaller ones are "
    "left-over pixels. A pixel count at reference_area_px: it scales with the image area.",
    {.unit = "px", .min = 1.0, .max = 1.0e7, .origin = "20-45 alike on generated sets"}};
const Param<double> kFrontBodyFaceRmsAt1mM{
    "front_body_face_rms_at_1m_m",
    0.0011,
    "A node is a flat face for front_body_margin_m when its plane fits its points within "
    "planar_max_rms_m (RMS) or within this times (depth / 1 m)^2: a flat face's disparity "
    "steps alone give it an RMS that grows with the square of its depth (about 3.3 mm at "
    "2 m for a Kinect), so far books and box tops are not planar by planar_max_rms_m.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "Kinect disparity steps (0.8 mm RMS at 1 m); 0.0008-0.0015 alike on "
               "generated sets"}};
const Param<bool> kFrontBodyKeepEnclosing{
    "front_body_keep_enclosing", true,
    "With front_body_margin_m: the bodies cut from one object that together reach around "
    "its faces in the image (their box holds the faces' box, short of it by a tenth of its "
    "size at most) are its walls, not bodies standing on it, and stay its own: an open "
    "container whose only patch is its floor. A can on a book stands on one side of the "
    "book's top or inside it, never around it."};
const Param<double> kFrontBodyBeyondMarginM{
    "front_body_beyond_margin_m",
    0.0,
    "With front_body_margin_m: a box's face spans the box in both directions of its plane, "
    "so left-over pixels that would join an object whose faces are all flat, but lie on none "
    "of their planes (within convex_tolerance_m) and beyond the extent of one of its "
    "planar faces (RMS within planar_max_rms_m) in that face's plane, by more than this plus "
    "front_body_beyond_band_px pixels at their depth, belong to another body too: a box or "
    "a can beside a box, lower than its top and not in front of its face. The extent runs "
    "along the face's principal directions and holds the object's faces on its plane too "
    "(pieces of one face). Faces flat only by front_body_face_rms_at_1m_m (far ones) bound "
    "nothing: their patch may cover a part of them. The shipped tabletop graphs set 0.01. "
    "0 = off.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "0.005-0.02 alike on generated sets (plateau); docs/evaluation.md"}};
const Param<double> kFrontBodyBeyondBandPx{
    "front_body_beyond_band_px",
    6.0,
    "With front_body_beyond_margin_m: the band of edge pixels a face's patch loses along its "
    "border, added to the margin at each pixel's depth (pixels x depth / fx).",
    {.unit = "px",
     .min = 0.0,
     .max = 100.0,
     .origin = "the edge band beside a crease (normals r = 2, edges over 3 px); 4-8 alike on "
               "generated sets"}};
const Param<double> kStepMinOffsetM{
    "step_min_offset_m",
    0.006,
    "Two planar patches that touch in the image, with normals within step_max_angle_deg and "
    "each centroid at least this far from the other's plane, are faces of two bodies: a "
    "convex body shows each direction on one face only (the fronts of a box on a box, two "
    "boxes side by side with one set back). A group that the edges join across such a pair "
    "is regrouped from its own edges, those whose patches touch along the most pixels first, "
    "leaving out each edge that would join the pair: a top that meets the other box's front "
    "at a corner, or that two flush boxes share, gives way before a long crease. 0 = off.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "measured on the 240 generated development frames: of 160 touching parallel "
               "planar pairs, the 104 standing 3 mm or more apart all held two objects, and "
               "the 50 of one object all stood closer; 0.004-0.008 alike (plateau), "
               "docs/evaluation.md"}};
const Param<double> kStepMaxAngleDeg{
    "step_max_angle_deg",
    15.0,
    "Most angle between the normals of a step pair's patches.",
    {.unit = "deg", .min = 0.0, .max = 90.0, .origin = "coplanar_max_angle_deg's 15 deg"}};
const Param<bool> kStepSplitFaces{
    "step_split_faces",
    true,
    "With step_min_offset_m: a planar patch that meets both faces of a separated step pair at "
    "convex creases of comparable length (the shorter at least 0.3 of the longer) spans the two "
    "bodies, like the flush front of two boxes whose tops stand a step apart. Its points are "
    "parted by the plane through the pair's seam (a line: its spread along at least 4 times "
    "its spread across) along their common normal, each side joining the object of the step "
    "face on that side, when each side holds at least a fifth of them. Off: the patch stays "
    "whole with one of the two.",
    {.origin = "own design; measured on the generated sets (docs/evaluation.md)"}};
const Param<bool> kEmitGraph{
    "emit_graph", false,
    "Fill the graph output. The runtime does not tell a stage whether an output is "
    "connected, so the graph is only built when asked for."};

}  // namespace

StageSpec PartitionGraph::spec() {
  return StageSpec(
             "partition.graph",
             "Objects as groups of a graph of surface patches (the authors' later algorithm).\n"
             "Nodes: every patch of a blob with at least min_patch_px points and a plane "
             "(least squares, normal towards the camera); planar when its points are within "
             "planar_max_rms_m (RMS) of the plane, else curved. A blob with no such patch is a "
             "node of its own. Edges, each feature switched by its bool: convex = adjacent "
             "patches of one blob at a convex junction (partition.convex's test: normals at "
             "least convex_min_angle_deg apart, each patch with convex_min_behind_share of its "
             "points not more than convex_tolerance_m in front of the other's plane); coplanar = "
             "two planar patches that do not touch, normals within coplanar_max_angle_deg, each "
             "centre within coplanar_max_distance_m of the other's plane, 3D boxes within "
             "coplanar_max_gap_m, whose gap in the image (coplanar_lines lines from one patch to "
             "the other) is occluded: at least coplanar_min_gap_px gap pixels with a point, and "
             "at least coplanar_min_front_share of them more than coplanar_front_margin_m in "
             "front of the common plane and of a blob other than the two patches' (a body "
             "touching them is no occluder unless it stands on their plane: "
             "coplanar_body_on_surface; pixels without a point count as neither); the two "
             "patches may be in different blobs, so an object may span blobs. curvature = two "
             "curved patches (any blobs) whose 3D boxes are within curvature_max_gap_m, or "
             "within curvature_max_occluded_gap_m with an occluded gap (as above), that one "
             "elliptic quadric fits (curvature_min_share of each within curvature_tolerance_m), "
             "or one circular cylinder (curvature_cylinder_max_radius_m); a curved patch and a "
             "smaller planar one of another blob within curvature_max_gap_m, that one closed "
             "quadric fits (curvature_flat_rims). "
             "floor = a planar patch and a larger curved one of its blob that touch, rise in "
             "front of its plane and wrap around its centre (a pot's floor and wall). "
             "Cut: while a group's "
             "minimum cut, each edge (i, j) costing 1/2 (1/deg_i + 1/deg_j), costs less than "
             "max_cut_cost and (cut_needs_cycles) each side holds a cycle, the group is split "
             "along it (weak bridges between densely joined groups). Steps: two planar patches "
             "that touch, face the same way (step_max_angle_deg) and stand step_min_offset_m or "
             "more apart are two bodies; a group holding such a pair is regrouped from its own "
             "edges, most contact first, leaving out those that would join the pair. Groups are "
             "objects. Before "
             "the other pixels of a blob (in no node, no point) are shared out, two kinds of "
             "body without a patch become objects: wide unclaimed cores "
             "(unclaimed_core_radius_px) and, with front_body_margin_m, pixels in front of a "
             "flat face of the object they would join. The rest "
             "join the object they are fewest pixel steps from within the blob. Object ids "
             "follow the raster order of each object's first pixel.")
      .declare(kBlobs, kPatches, kAdjacency, kPoints, kObjects, kGraph, kMinPatchPx, kPlanarMaxRmsM,
               kConvex, kConvexToleranceM, kConvexMinBehindShare, kConvexMinAngleDeg, kCoplanar,
               kCoplanarMaxAngleDeg, kCoplanarMaxDistanceM, kCoplanarMaxGapM, kCoplanarFrontMarginM,
               kCoplanarMinFrontShare, kCoplanarMinGapPx, kCoplanarLines, kCoplanarAcrossBlobsOnly,
               kCoplanarTouchingMaxDistanceM, kCoplanarBodyOnSurface, kMaxPartners, kCurvature,
               kCurvatureToleranceM, kCurvatureMinShare, kCurvatureMinAxisRatio, kCurvatureSamples,
               kCurvatureMaxGapM, kCurvatureMaxOccludedGapM, kCurvatureCylinderMaxRadiusM,
               kCurvatureFlatRims, kFloor, kFloorMinRiseM, kFloorMinWrapDeg, kCut, kMaxCutCost,
               kCutNeedsCycles, kMaxCutNodes, kUnclaimedCoreRadiusPx, kUnclaimedCoreMinPx,
               kUnclaimedCoreRadiusM, kFrontBodyMarginM, kFrontBodyMinPx, kFrontBodyFaceRmsAt1mM,
               kFrontBodyKeepEnclosing, kFrontBodyBeyondMarginM, kFrontBodyBeyondBandPx,
               kStepMinOffsetM, kStepMaxAngleDeg, kStepSplitFaces, kEmitGraph,
               algo::kReferenceAreaParam)
      .concurrency(Concurrency::clonable);
}

PartitionGraph::PartitionGraph(const Params& params)
    : emit_graph_(kEmitGraph(params)), reference_area_px_(algo::kReferenceAreaParam(params)) {
  core_rule_ = {kUnclaimedCoreRadiusPx(params), kUnclaimedCoreRadiusM(params),
                kUnclaimedCoreMinPx(params), kConvexToleranceM(params)};
  front_rule_ = {kFrontBodyMarginM(params),       kFrontBodyMinPx(params),
                 kPlanarMaxRmsM(params),          kFrontBodyFaceRmsAt1mM(params),
                 kFrontBodyKeepEnclosing(params), kFrontBodyBeyondMarginM(params),
                 kFrontBodyBeyondBandPx(params),  kConvexToleranceM(params)};
  rule_.nodes = {kMinPatchPx(params), kPlanarMaxRmsM(params)};
  rule_.convex = kConvex(params);
  rule_.convex_rule = {kConvexToleranceM(params), kConvexMinBehindShare(params),
                       kConvexMinAngleDeg(params), rule_.nodes.min_patch_px};
  rule_.coplanar = kCoplanar(params);
  rule_.coplanar_rule = {kCoplanarMaxAngleDeg(params),     kCoplanarMaxDistanceM(params),
                         kCoplanarMaxGapM(params),         kCoplanarFrontMarginM(params),
                         kCoplanarMinFrontShare(params),   kCoplanarMinGapPx(params),
                         kCoplanarLines(params),           kMaxPartners(params),
                         kCoplanarAcrossBlobsOnly(params), kCoplanarTouchingMaxDistanceM(params),
                         kCoplanarBodyOnSurface(params)};
  rule_.curvature = kCurvature(params);
  rule_.curvature_rule = {kCurvatureToleranceM(params),
                          kCurvatureMinShare(params),
                          kCurvatureMinAxisRatio(params),
                          kCurvatureSamples(params),
                          kCurvatureMaxGapM(params),
                          kCurvatureMaxOccludedGapM(params),
                          kCurvatureCylinderMaxRadiusM(params),
                          kCurvatureFlatRims(params)};
  rule_.floor = kFloor(params);
  rule_.floor_rule = {kFloorMinRiseM(params), kFloorMinWrapDeg(params)};
  rule_.steps = {kStepMinOffsetM(params), kStepMaxAngleDeg(params)};
  rule_.span_split.enabled = kStepSplitFaces(params);
  rule_.cut = {kCut(params), kMaxCutCost(params), kMaxCutNodes(params), kCutNeedsCycles(params)};
}

// The rules in pixels, scaled to the frame's resolution; the edge bands (front_body_beyond_band_px)
// and the gap evidence (coplanar_min_gap_px) are properties of the image and stay as given.
PartitionGraph::FrameRules PartitionGraph::rules_for(cv::Size image) const {
  const algo::PixelScale scale(reference_area_px_, image);
  FrameRules rules{rule_.nodes, rule_.convex_rule, core_rule_, front_rule_};
  rules.nodes.min_patch_px = scale.count(rule_.nodes.min_patch_px, 3);
  rules.convex.min_patch_px = rules.nodes.min_patch_px;
  rules.core.radius_px = scale.length(core_rule_.radius_px);
  rules.core.min_px = scale.count(core_rule_.min_px);
  rules.front.min_px = scale.count(front_rule_.min_px);
  return rules;
}

void PartitionGraph::process(ProcessContext& ctx) {
  const auto& blobs = kBlobs(ctx);
  const auto& patches = kPatches(ctx);
  const auto& adjacency = kAdjacency(ctx);
  const auto& points = kPoints(ctx);
  graph_.nodes.clear();
  check_partition_inputs(blobs.labels, patches.labels, points.points);
  const FrameRules rules = rules_for(blobs.labels.size());
  // The gap lines read the images as flat arrays, which packet images are (facet/types/images.hpp).
  const FrameImages images{&patches.labels, &points.points, &blobs.labels};
  segments_.build(blobs.labels, patches.labels, points.points);
  neighbours_.build(adjacency, segments_.max_patch);
  graph_.build(segments_, blobs.labels.cols, rules.nodes);

  edges_.clear();
  if (rule_.convex) {
    add_convex_edges(segments_, graph_, neighbours_, rules.convex, node_of_patch_, edges_);
  }
  const std::size_t convex_count = edges_.size();
  const TouchingNodes touching = touching_nodes(graph_, neighbours_);
  if (rule_.coplanar) {
    add_coplanar_edges(segments_, graph_, images, touching, rule_.coplanar_rule, edges_);
  }
  const std::size_t coplanar_count = edges_.size() - convex_count;
  if (rule_.curvature) {
    add_curvature_edges(segments_, graph_, images, rule_.coplanar_rule, rule_.curvature_rule,
                        edges_);
  }
  const std::size_t curvature_count = edges_.size() - convex_count - coplanar_count;
  if (rule_.floor) {
    add_floor_edges(segments_, graph_, images, touching, rule_.floor_rule, edges_);
  }
  const std::size_t floor_count = edges_.size() - convex_count - coplanar_count - curvature_count;

  for (GraphEdge& edge : edges_) {
    edge.contact_px = neighbours_.contact_px(graph_.nodes[static_cast<std::size_t>(edge.a)].patch,
                                             graph_.nodes[static_cast<std::size_t>(edge.b)].patch);
  }
  const StepPairs steps = find_step_pairs(graph_, touching, rule_.steps);

  const auto node_count = static_cast<std::int32_t>(graph_.nodes.size());
  const std::vector<std::int32_t>& group = cut_.groups(node_count, edges_, rule_.cut, steps);
  const std::vector<SpanSplit> splits =
      find_span_splits(segments_, graph_, patches.labels, edges_, steps, group, rule_.span_split);
  split_of_node_.assign(graph_.nodes.size(), -1);
  for (std::size_t k = 0; k < splits.size(); ++k)
    split_of_node_[static_cast<std::size_t>(splits[k].node)] = static_cast<std::int32_t>(k);
  cv::Mat objects = cv::Mat::zeros(blobs.labels.size(), CV_32SC1);
  auto* labels = objects.ptr<std::int32_t>();
  // The cores need each claimed pixel's node and the planar nodes' planes (a core that continues
  // one of those faces is that face).
  const bool cores = rules.core.radius_px > 0.0;
  std::int32_t* node_of = nullptr;
  if (cores) {
    node_of_pixel_.create(blobs.labels.size(), CV_32SC1);
    node_of_pixel_.setTo(-1);
    node_of = node_of_pixel_.ptr<std::int32_t>();
    face_planes_.assign(graph_.nodes.size(), FittedPlane{});
  }
  std::int32_t next_id = 1;
  for (std::int32_t i = 0; i < node_count; ++i) {
    const GraphNode& node = graph_.nodes[static_cast<std::size_t>(i)];
    const std::int32_t id = 1 + group[static_cast<std::size_t>(i)];
    next_id = std::max(next_id, id + 1);
    if (node.segment < 0) continue;  // a patchless blob: fill_blob_gaps gives it its own id
    if (cores && node.planar) face_planes_[static_cast<std::size_t>(i)] = node.plane;
    const Segment& segment = segments_.segments[static_cast<std::size_t>(node.segment)];
    const std::int32_t split = split_of_node_[static_cast<std::size_t>(i)];
    for (std::int32_t k = segment.begin; k < segment.end; ++k) {
      const auto point = static_cast<std::size_t>(k);
      const std::int32_t pixel = segments_.pixel[point];
      labels[pixel] = split < 0
                          ? id
                          : 1 + splits[static_cast<std::size_t>(split)].group_at(
                                    segments_.x[point], segments_.y[point], segments_.z[point]);
      if (cores) node_of[pixel] = i;
    }
  }
  if (cores) {
    next_id = claim_unclaimed_cores(objects, blobs.labels, points.points, points.camera.fx,
                                    ClaimedFaces{&node_of_pixel_, &face_planes_}, rules.core,
                                    core_buffers_, next_id);
  }
  if (rules.front.margin_m > 0.0) {
    flat_faces_of_objects(graph_, segments_, group, next_id, rules.front, faces_of_object_);
    next_id = claim_bodies_in_front(objects, blobs.labels, points.points, faces_of_object_,
                                    rules.front, points.camera.fx, front_buffers_, next_id);
    fill_blob_gaps(objects, blobs.labels, next_id, front_buffers_.gaps);
  } else {
    fill_blob_gaps(objects, blobs.labels, next_id);
  }
  const std::int32_t count = relabel_in_raster_order(objects);
  LabelImage object_image = LabelImage::make(blobs, std::move(objects), count);
  ctx.metric("objects", count);
  ctx.metric("nodes", static_cast<double>(graph_.nodes.size()));
  ctx.metric("convex_edges", static_cast<double>(convex_count));
  ctx.metric("coplanar_edges", static_cast<double>(coplanar_count));
  ctx.metric("curvature_edges", static_cast<double>(curvature_count));
  ctx.metric("floor_edges", static_cast<double>(floor_count));
  ctx.metric("cuts", static_cast<double>(cut_.cuts()));
  ctx.metric("step_pairs", static_cast<double>(steps.size()));
  ctx.metric("step_separations", static_cast<double>(cut_.step_separations()));
  ctx.metric("split_faces", static_cast<double>(splits.size()));
  if (emit_graph_) {
    kGraph(ctx, make_patch_graph(object_image, graph_, edges_, group));
  }
  kObjects(ctx, std::move(object_image));
}

}  // namespace facet::partition
