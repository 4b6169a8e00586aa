#include "planes/support_planes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "facet/algo/label_runs.hpp"
#include "facet/algo/patch_contacts.hpp"
#include "facet/algo/pixel_scale.hpp"
#include "facet/contract.hpp"
#include "facet/image_checks.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "planes/candidate_planes.hpp"
#include "planes/plane_assignment.hpp"
#include "planes/scene_model.hpp"
#include "planes/table_outline.hpp"
#include "planes/world_up.hpp"

namespace facet::planes {
namespace {

const In<LabelImage> kPatchesIn{"patches",
                                "Surface patches, CV_32SC1 ids 1..count (grow.surfaces)."};
const In<PointImage> kPoints{"points", "3D points, CV_32FC3 in metres, NaN = invalid; same size."};
const Out<SupportPlanes> kPlanes{
    "planes",
    "Support planes (ids 1..N, largest candidate first; normal towards "
    "the camera, inliers, rms, horizontal, role: table, floor or wall), "
    "world up, the table's id and its outline."};
const Out<LabelImage> kPlaneLabels{"plane_labels", "CV_32SC1 plane id per pixel, 0 = on no plane."};
const Out<LabelImage> kPatchesOut{
    "patches",
    "The input patches with plane points and dropped segments set to 0; "
    "ids kept (ids may now be unused); the pieces a plane cut off a "
    "patch numbered from the input's count + 1 on."};
const Out<PatchAdjacency> kAdjacency{"adjacency",
                                     "Pairs (a < b, sorted) of the output patches that touch "
                                     "(8-neighbours), as grow.surfaces' adjacency, for the patches "
                                     "left."};
const Param<double> kDistance{
    "distance_m",
    0.010,
    "delta: a point closer than this to a support plane belongs to it. RANSAC scores "
    "its hypotheses at delta / 2.",
    {.unit = "m",
     .min = 0.001,
     .max = 0.5,
     .origin = "paper: 12 mm; swept 8-14 mm: 10 mm lies on the plateau of mOSD and of "
               "both generated sets, 12 mm not on that of the tuning set "
               "(docs/evaluation.md)"}};
const Param<int> kRansacIterations{
    "ransac_iterations",
    20,
    "Random 3-point hypotheses per candidate, at least. Samples come from one surface "
    "patch, which is mostly one plane, so a few suffice; where the best hypothesis holds "
    "less of the patch, ransac_confidence asks for more.",
    {.min = 1.0, .max = 10000.0, .origin = "authors' code (20)"}};
const Param<double> kRansacConfidence{
    "ransac_confidence",
    0.95,
    "Adaptive RANSAC: more hypotheses than ransac_iterations, up to "
    "ransac_max_iterations, until a triple of inliers of the best plane so far has been "
    "drawn with this probability, 1 - (1 - w^3)^n at its inlier share w. A patch "
    "that spans a table, the floor below it and the objects on it (where no normal "
    "edge closed between them) may hold the table's plane in a third of its points; "
    "20 triples then find it 4 times in 10. 0 = exactly ransac_iterations.",
    {.min = 0.0,
     .max = 0.999999,
     .origin = "the textbook stopping rule (Fischler and Bolles; Hartley and Zisserman "
               "4.7.1); 0.95-0.999 score alike on the generated sets, 0.95 draws the "
               "fewest (docs/planes.md)"}};
const Param<int> kRansacMaxIterations{
    "ransac_max_iterations",
    500,
    "The most hypotheses ransac_confidence may ask for per fit (at 0.95 the rule needs 110 at "
    "an inlier share of 0.3, 2 995 at 0.1).",
    {.min = 1.0, .max = 100000.0, .origin = "bounds the time of a patch with no plane"}};
const Param<std::int64_t> kCandidateMinSize{
    "candidate_min_px",
    2500,
    "N_bg: patches with at least this many valid points are plane candidates. Low "
    "enough for wall and floor fragments at the edge of the view; box faces among "
    "the candidates are rejected by the support test, not by size. A pixel count at "
    "reference_area_px: it scales with the image area.",
    {.unit = "px",
     .min = 3.0,
     .max = 1.0e8,
     .origin = "paper's N_bg = 2500, here at 640x480 (the authors' 320x240 value x4, "
               "10000, leaves wall fragments of the uncropped OSD frame as objects)"}};
const Param<int> kMaxCandidates{
    "max_candidates",
    16,
    "The largest this many candidates are fitted and judged.",
    {.min = 1.0,
     .max = 32.0,
     .origin = "measured: the 45 mOSD frames have at most 8 patches over 10000 px"}};
const Param<std::int64_t> kFitMaxPoints{
    "fit_max_points",
    10000,
    "A candidate's plane is fitted (RANSAC and least-squares refit) to at most this "
    "many of its points, every k-th in raster order.",
    {.min = 3.0,
     .max = 1.0e8,
     .origin = "measured: same planes and scores on mOSD as with all points, a "
               "fraction of the time"}};
const Param<double> kObjectFaceOffPlaneFraction{
    "object_face_off_plane_fraction",
    0.5,
    "A patch with at least this share of its points more than 2 distance_m from every "
    "support plane is an object face: its points within distance_m of a plane stay "
    "with it (the bottom band of an object standing on the table). So is a patch whose "
    "points near a horizontal plane lie on average more than min_object_height_m above "
    "it (a book 1 cm thick). Other points within distance_m join the plane. Above 1, "
    "only the height test keeps points from the planes.",
    {.min = 0.0,
     .max = 2.0,
     .origin = "measured on mOSD: recall of objects' lower borders (docs/planes.md)"}};
const Param<double> kMinViewFraction{
    "min_view_fraction",
    0.01,
    "A plane that is not the dominant horizontal one must hold at least this share of "
    "the valid pixels (sampled, within distance_m) to be background.",
    {.min = 0.0,
     .max = 1.0,
     .origin = "measured: the wall fragment of the uncropped OSD frame holds 0.02"}};
const Param<double> kMaxBehindFraction{
    "max_behind_fraction",
    0.05,
    "A plane that is not the dominant horizontal one is background only if at most "
    "this share of the object candidates lies behind it.",
    {.min = 0.0, .max = 1.0, .origin = "measured on mOSD and the uncropped OSD frame"}};
const Param<double> kBehindMargin{
    "behind_margin_m",
    0.05,
    "A point counts as behind a plane when it is further than this on the plane's far "
    "side: sensor noise, mixed pixels and the front edge of a table top (a few cm "
    "thick) stay within it, while a box's far side lies beyond.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "measured: 0.03 and 0.05 score alike on mOSD and the uncropped OSD "
               "frame; 0.05 keeps a 4 cm table top in front of a dominant floor"}};
const Param<double> kMinObjectFraction{
    "min_object_fraction",
    0.02,
    "Floor of the behind-test denominator, as a share of the valid pixels, so that a "
    "few stray points do not veto a plane when almost nothing else is left.",
    {.min = 0.0, .max = 1.0, .origin = "measured"}};
const Param<double> kMaxSupportBehindFraction{
    "max_support_behind_fraction",
    0.1,
    "An object face stands on the table: a candidate with more than this share of the "
    "dominant plane's points behind it is not background (unless it holds "
    "large_view_fraction of the view).",
    {.min = 0.0, .max = 1.0, .origin = "measured on mOSD and the uncropped OSD frame"}};
const Param<double> kLargeViewFraction{
    "large_view_fraction",
    0.15,
    "Horizontal candidates (within horizontal_max_deg of up) holding this share of the "
    "valid pixels skip the max_support_behind_fraction test (a table seen above a "
    "dominant floor); a large vertical face standing on the table stays an object.",
    {.min = 0.0, .max = 1.0, .origin = "measured: mOSD box faces hold at most 0.13"}};
const Param<int> kSampleStride{
    "sample_stride_px",
    4,
    "The support test looks at every n-th row and column (the assignment to planes "
    "is always per pixel).",
    {.unit = "px",
     .min = 1.0,
     .max = 16.0,
     .origin = "measured: the same decisions at 1, 2 and 4 on mOSD and the uncropped "
               "OSD frame; 4 reads 1/16 of the points"}};
const Param<double> kMinObjectHeight{
    "min_object_height_m",
    0.006,
    "Scene model: horizontal candidates whose centroids lie within this height of one "
    "another's plane are one level (the fragments of one table top); a level or a patch "
    "raised above the table by more is the top of an object lying on it. The smallest "
    "thickness of a flat object that is found (with Kinect noise at 1 m: about 1 cm).",
    {.unit = "m",
     .min = 0.0,
     .max = 0.1,
     .origin = "measured: plateau of generated scenes with books 1-4 cm thick "
               "(docs/evaluation.md)"}};
const Param<double> kMaxObjectHeight{
    "max_object_height_m",
    0.3,
    "Scene model: a horizontal level raised above the table by up to this much is an "
    "object top; farther above, and holding large_view_fraction of the view, it is a "
    "table above the floor. A level this much or less below the largest one, holding "
    "min_table_fraction, is the table that level stands on.",
    {.unit = "m",
     .min = 0.0,
     .max = 10.0,
     .origin = "tables stand 0.4 m and more above the floor; objects for a gripper are "
               "lower"}};
const Param<double> kMinTableFraction{
    "min_table_fraction",
    0.05,
    "Scene model: the least share of the valid pixels that a level below the largest "
    "one needs to be taken for the table (the largest level is then a board lying on "
    "it).",
    {.min = 0.0, .max = 1.0, .origin = "measured on generated crowded tables"}};
const Param<double> kMinTableUnderShare{
    "min_table_under_share",
    0.25,
    "Scene model: a level below the largest one is the table that level stands on only "
    "when at least this share of the largest level's points, seen from above, lies inside "
    "the lower level's convex outline. A board lying on a table has the table around or "
    "behind it; a chair's seat beside a low table, a centimetre lower, lies beside it and "
    "would take the objects' table away.",
    {.min = 0.0,
     .max = 1.0,
     .origin = "a low table beside a chair (a RealSense frame); docs/planes.md"}};
const Param<double> kHorizontalMaxAngle{
    "horizontal_max_deg",
    10.0,
    "alpha_z: a plane is horizontal when its normal is within this angle of world up.",
    {.unit = "deg", .min = 0.0, .max = 90.0, .origin = "paper (10 deg)"}};
const Param<WorldUp> kUp{
    "up",
    WorldUp{},
    "World up in the camera frame: 'auto' takes the normal of the largest candidate "
    "within up_prior_max_deg of the camera's up (-y); or a vector 'x,y,z' (camera "
    "frame: x right, y down, z forward), e.g. '0,-1,0' for a level camera.",
    {.origin = "ALGORITHM.md: from a parameter or the dominant horizontal plane"}};
const Param<double> kUpPriorMaxAngle{
    "up_prior_max_deg",
    80.0,
    "auto up: the dominant horizontal plane is the largest candidate whose normal is "
    "within this angle of the camera's -y axis (a camera looking down at a table at "
    "up to this pitch). A wall facing a camera pitched down lies more than 90 deg from "
    "it. With a given up, horizontal_max_deg is used instead.",
    {.unit = "deg",
     .min = 0.0,
     .max = 90.0,
     .origin = "mOSD tables 25-50 deg; generated views pitched down 30-70 deg (60 lost "
               "the table of every view pitched more steeply, docs/evaluation.md)"}};
const Param<std::int64_t> kMinSegmentSize{
    "min_segment_px",
    20,
    "N_seg: patches left with fewer points than this are dropped (set to 0). A pixel count at "
    "reference_area_px: it scales with the image area.",
    {.unit = "px", .min = 0.0, .max = 1.0e6, .origin = "paper: N_seg = 5 at 320x240, x4"}};
const Param<double> kSplitMaxDistance{
    "split_max_distance_m",
    0.01,
    "Gate of the split of what a plane leaves of a patch: two of its pixels are one "
    "piece when they are 8-neighbours closer than this in 3D (growing with the square "
    "of the depth beyond split_growth_start_m).",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "grow.blobs' Delta_blob (the same neighbour linkage)"}};
const Param<double> kSplitGrowthStart{
    "split_growth_start_m",
    1.2,
    "Beyond this depth split_max_distance_m grows with the square of the depth; 0 "
    "keeps it fixed.",
    {.unit = "m", .min = 0.0, .max = 100.0, .origin = "grow.blobs' distance_growth_start_m"}};
const Param<int> kPlanesPerPatch{
    "planes_per_patch",
    2,
    "Planes fitted to one candidate patch: what a fit leaves more than 2 distance_m "
    "off its plane, when that is at least candidate_min_px, is fitted again (a fit "
    "within horizontal_max_deg and 2 distance_m of the one before is the same plane "
    "and ends the search). Where no normal edge parts them, one patch spans a far table "
    "and the wall behind it; one plane per patch then finds only the wall, and the "
    "frame loses its table. 1 = the paper's one plane per patch.",
    {.min = 1.0,
     .max = 4.0,
     .origin = "2: generated checking set with PCA normals 0.835 -> 0.890 (seed 1008's "
               "view lost its table); the default graph's figures unchanged within "
               "0.001 (docs/planes.md)"}};
const Param<int> kFlatObjectWindow{
    "flat_object_window_px",
    9,
    "Flat objects the table took (docs/planes.md, rule 7): the heights of the table's points "
    "above its plane are averaged over windows of this side; where the mean exceeds "
    "min_object_height_m over at least flat_object_min_px connected table pixels, and the "
    "region's border is a step of flat_object_min_step_m, the region leaves the table as a "
    "patch of its own (a book or magazine about 1 cm thick, whose top grew into the table's "
    "patch because no normal edge closed around it). 0 = off.",
    {.unit = "px",
     .min = 0.0,
     .max = 101.0,
     .origin = "measured on the generated development sets: 7-11 within 0.002 of it on "
               "every set; no region of the real mOSD tables passes (docs/evaluation.md)"}};
const Param<double> kFlatObjectMinStep{
    "flat_object_min_step_m",
    0.004,
    "Border test of a raised region: the median height of its points 2 px and more inside "
    "it must exceed that of the table 2-6 px outside it by this much. A warped or noisy "
    "table rises slowly and fails; a flat object's edge is a step of its thickness.",
    {.unit = "m",
     .min = 0.0,
     .max = 0.1,
     .origin = "measured: flat objects found on the generated sets step 5.6-8.1 mm; the "
               "raised regions of real mOSD tables 2.4 and 3.2 mm (docs/evaluation.md)"}};
const Param<std::int64_t> kFlatObjectMinSize{
    "flat_object_min_px",
    300,
    "Raised regions with fewer table pixels stay with the table. A pixel count at "
    "reference_area_px: it scales with the image area.",
    {.unit = "px",
     .min = 1.0,
     .max = 1.0e8,
     .origin = "measured: the flat objects of the generated sets give 500-5600 px"}};
const Param<double> kFlatObjectMinWidth{
    "flat_object_min_width_px",
    12.0,
    "Raised regions narrower than this (twice the largest distance of a point from the "
    "region's border, small holes closed) stay with the table: the strips along the feet of "
    "objects, where their sides' bottom bands and the table around them average above "
    "min_object_height_m. A width at reference_area_px: it scales with the square root of the "
    "image area.",
    {.unit = "px",
     .min = 0.0,
     .max = 1000.0,
     .origin = "measured: 8-16 score alike on the generated sets; 8 takes a strip along an "
               "object's foot from the table of a real YCB-Video frame, 12 does not "
               "(docs/evaluation.md)"}};
const Param<double> kFlatObjectMaxHeight{
    "flat_object_max_height_m",
    0.02,
    "Rule 7 also averages the points on no plane that lie within this height of the table, "
    "when they are in a piece of a patch a plane cut that lies that low throughout: the upper "
    "half of a 1 cm book's noisy top, which the table's plane left as stripes. The raised "
    "region then stays whole and its mean height is the book's, and the stripes inside it join "
    "its patch, with its edge pixels that lie that low. 0 = the table's points only.",
    {.unit = "m",
     .min = 0.0,
     .max = 0.1,
     .origin = "measured on the generated development sets: books 1 cm thick 1.2-2.2 m away "
               "(docs/evaluation.md)"}};
const Param<std::int64_t> kSeed{
    "seed",
    1,
    "Seed of the RANSAC random numbers, reset every frame.",
    {.min = 0.0, .max = 4294967295.0, .origin = "any; fixed for reproducible results"}};

// The table's outline is the hull of the points on every 8th row and column: a few thousand of
// them, whose hull is within a few millimetres of the full one.
constexpr int kOutlineStridePx = 8;
// A patch outlines the table when at least this share of its points lies on the table's level.
constexpr double kOutlinePatchShare = 0.25;

// The valid pixels of the frame, counted on every 4th row (the level sizes they are compared
// with are coarse shares of the view).
std::int64_t estimate_valid_px(const cv::Mat& xyz) {
  constexpr int kRowStep = 4;
  std::int64_t valid = 0;
  for (int row = 0; row < xyz.rows; row += kRowStep) {
    const auto* p = xyz.ptr<float>(row);
    for (int col = 0; col < xyz.cols; ++col)
      valid += std::isfinite(p[3 * col + 2]) ? 1 : 0;
  }
  return valid * kRowStep;
}

// The accepted candidates in candidate order, with their role in the scene model and the
// index of the table's plane among them (-1: none).
struct AcceptedPlanes {
  std::vector<algo::Plane> models;
  std::vector<PlaneRole> roles;
  int table = -1;
};

AcceptedPlanes accepted_planes(const std::vector<CandidatePlane>& candidates,
                               const TableChoice& table,
                               const std::vector<CandidateEvidence>& evidence,
                               const Eigen::Vector3f& up, double min_cos_horizontal) {
  AcceptedPlanes out;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!evidence[c].accepted) continue;
    const algo::Plane& model = candidates[c].model;
    out.models.push_back(model);
    const bool horizontal = model.normal.dot(up) >= min_cos_horizontal;
    if (table.table >= 0 && table.roles[c] == CandidateRole::table) {
      out.roles.push_back(PlaneRole::table);
      if (static_cast<int>(c) == table.table) out.table = static_cast<int>(out.models.size()) - 1;
    } else if (horizontal && table.table >= 0 && table.height_m[c] < 0.0F) {
      out.roles.push_back(PlaneRole::floor);
    } else {
      out.roles.push_back(PlaneRole::wall);
    }
  }
  return out;
}

// The table's patches: those of which a good share lies on a plane of the table's level. A share,
// not a majority: beyond 2 m a table's own disparity steps put much of it more than delta off.
std::vector<char> table_patches(const PlaneAssignment& assignment,
                                const std::vector<PlaneRole>& roles) {
  const std::size_t plane_count = roles.size();
  const std::size_t patch_slots = assignment.patch_px.size();
  std::vector<char> out(patch_slots, 0);
  for (std::size_t slot = 1; slot < patch_slots; ++slot) {
    std::int64_t on_table_px = 0;
    for (std::size_t c = 0; c < plane_count; ++c) {
      if (roles[c] == PlaneRole::table) on_table_px += assignment.near_px[slot * plane_count + c];
    }
    out[slot] = static_cast<double>(on_table_px) >=
                kOutlinePatchShare * static_cast<double>(assignment.patch_px[slot]);
  }
  return out;
}

}  // namespace

StageSpec SupportPlaneStage::spec() {
  StageSpec spec(
      "planes.support",
      "Support and background planes (table, floor, walls) from large surface patches.\n"
      "Paper sec. II-B d. Every patch of at least candidate_min_px valid points is a "
      "candidate (largest first, at most max_candidates): a plane is fitted to it by "
      "ransac_iterations random point triples of the patch, scored at distance_m / 2, "
      "then refitted by least squares. The scene model (docs/planes.md) first picks the "
      "table: horizontal candidates are grouped into levels (centroids within "
      "min_object_height_m of one plane); the largest level is the table, unless a level "
      "far above it (max_object_height_m) holds large_view_fraction of the view (a table "
      "above the floor) or a level a little below it holds min_table_fraction (the "
      "largest level is then a board or box lying on that table). Levels raised above "
      "the table by up to max_object_height_m are object tops (books, trays, boxes lying "
      "flat) and never support planes. Any other candidate becomes a background plane "
      "when it covers at least min_view_fraction of the valid pixels and at most "
      "max_behind_fraction of the object candidates (points on no support plane) lie "
      "more than behind_margin_m behind it; this is re-evaluated until nothing changes, "
      "so a table is accepted once the floor and walls behind it are. Box faces fail: "
      "the rest of their box lies behind them. Then, largest first, every valid point "
      "not yet taken within distance_m of a support plane joins it, also out of its "
      "patch, except the points of object faces. What a plane leaves of a patch is split "
      "into its connected pieces (8-neighbours closer than split_max_distance_m), each a "
      "patch of its own: a table patch that ran onto the tops of objects leaves one "
      "piece per top, not one patch spanning them. Patches left with fewer than "
      "min_segment_px points are dropped. A region of the table's points whose mean height "
      "above it over flat_object_window_px windows exceeds min_object_height_m, at least "
      "flat_object_min_px large and flat_object_min_width_px wide, with a border that steps "
      "flat_object_min_step_m, leaves the table as a patch of its own (a book whose top grew "
      "into the table's patch). The table's visible extent (a convex outline) "
      "goes with the planes, for grow.blobs.");
  return spec
      .declare(kPatchesIn, kPoints, kPlanes, kPlaneLabels, kPatchesOut, kAdjacency, kDistance,
               kRansacIterations, kRansacConfidence, kRansacMaxIterations, kCandidateMinSize,
               kMaxCandidates, kFitMaxPoints, kObjectFaceOffPlaneFraction, kMinViewFraction,
               kMaxBehindFraction, kBehindMargin, kMinObjectFraction, kMaxSupportBehindFraction,
               kLargeViewFraction, kSampleStride, kMinObjectHeight, kMaxObjectHeight,
               kMinTableFraction, kMinTableUnderShare, kHorizontalMaxAngle, kUp, kUpPriorMaxAngle,
               kMinSegmentSize, kSplitMaxDistance, kSplitGrowthStart, kPlanesPerPatch,
               kFlatObjectWindow, kFlatObjectMinStep, kFlatObjectMinSize, kFlatObjectMinWidth,
               kFlatObjectMaxHeight, kSeed, algo::kReferenceAreaParam)
      .concurrency(Concurrency::clonable);
}

SupportPlaneStage::SupportPlaneStage(const Params& params)
    : horizontal_max_deg_(kHorizontalMaxAngle(params)),
      up_prior_max_deg_(kUpPriorMaxAngle(params)),
      up_(kUp(params).direction),
      min_segment_px_(kMinSegmentSize(params)),
      reference_area_px_(algo::kReferenceAreaParam(params)),
      split_gate_(static_cast<float>(kSplitMaxDistance(params)),
                  static_cast<float>(kSplitGrowthStart(params))),
      seed_(static_cast<std::uint32_t>(kSeed(params))) {
  const auto distance_m = static_cast<float>(kDistance(params));
  fit_rule_.iterations = kRansacIterations(params);
  fit_rule_.confidence = kRansacConfidence(params);
  fit_rule_.max_iterations = std::max(fit_rule_.iterations, kRansacMaxIterations(params));
  fit_rule_.inlier_distance_m = distance_m / 2.0F;
  support_rule_.inlier_distance_m = distance_m;
  support_rule_.behind_margin_m = static_cast<float>(kBehindMargin(params));
  support_rule_.min_view_fraction = kMinViewFraction(params);
  support_rule_.max_behind_fraction = kMaxBehindFraction(params);
  support_rule_.min_object_fraction = kMinObjectFraction(params);
  support_rule_.max_support_behind_fraction = kMaxSupportBehindFraction(params);
  support_rule_.large_view_fraction = kLargeViewFraction(params);
  support_rule_.min_cos_horizontal = std::cos(horizontal_max_deg_ * std::numbers::pi / 180.0);
  support_rule_.sample_stride_px = kSampleStride(params);
  table_rule_.min_cos_horizontal = support_rule_.min_cos_horizontal;
  table_rule_.level_tolerance_m = static_cast<float>(kMinObjectHeight(params));
  table_rule_.max_object_height_m = static_cast<float>(kMaxObjectHeight(params));
  table_rule_.min_table_fraction = kMinTableFraction(params);
  table_rule_.min_table_under_share = kMinTableUnderShare(params);
  table_rule_.large_view_fraction = support_rule_.large_view_fraction;
  candidate_rule_.min_px = kCandidateMinSize(params);
  candidate_rule_.max_candidates = kMaxCandidates(params);
  candidate_rule_.max_fit_points = kFitMaxPoints(params);
  candidate_rule_.planes_per_patch = kPlanesPerPatch(params);
  candidate_rule_.off_plane_m = 2.0F * distance_m;
  candidate_rule_.same_plane_cos = static_cast<float>(support_rule_.min_cos_horizontal);
  assignment_rule_.inlier_distance_m = distance_m;
  assignment_rule_.object_face_off_plane_fraction = kObjectFaceOffPlaneFraction(params);
  assignment_rule_.min_object_height_m = static_cast<float>(kMinObjectHeight(params));
  flat_object_rule_.window_px = kFlatObjectWindow(params);
  flat_object_rule_.min_height_m = static_cast<float>(kMinObjectHeight(params));
  flat_object_rule_.min_step_m = static_cast<float>(kFlatObjectMinStep(params));
  flat_object_rule_.min_px = kFlatObjectMinSize(params);
  flat_object_rule_.min_width_px = kFlatObjectMinWidth(params);
  flat_object_rule_.max_height_m = static_cast<float>(kFlatObjectMaxHeight(params));
}

void SupportPlaneStage::process(ProcessContext& ctx) {
  const LabelImage& patches = kPatchesIn(ctx);
  const PointImage& points = kPoints(ctx);
  require_same_size(patches.labels, "patches", points.points, "points");
  const cv::Mat& labels = patches.labels;
  const cv::Mat& xyz = points.points;

  // The rules in pixels, for this frame's resolution.
  const algo::PixelScale scale(reference_area_px_, xyz.size());
  CandidateRule candidate_rule = candidate_rule_;
  candidate_rule.min_px = scale.count(candidate_rule_.min_px, 3);
  FlatObjectRule flat_object_rule = flat_object_rule_;
  flat_object_rule.min_px = scale.count(flat_object_rule_.min_px);
  flat_object_rule.min_width_px = scale.length(flat_object_rule_.min_width_px);
  const std::int64_t min_segment_px = scale.count(min_segment_px_, 0);

  // Candidates and their planes; the generator restarts every frame, so a frame's result does
  // not depend on the frames before it (and clones agree).
  std::mt19937 rng(seed_);
  const std::vector<CandidatePlane> candidates =
      find_candidate_planes(labels, xyz, patches.count, candidate_rule, fit_rule_, rng);
  std::vector<algo::Plane> models;
  std::vector<std::int64_t> sizes;
  std::vector<Eigen::Vector3f> centroids;
  std::vector<std::vector<Eigen::Vector3f>> footprints;
  for (const CandidatePlane& candidate : candidates) {
    models.push_back(candidate.model);
    sizes.push_back(candidate.size_px);
    centroids.push_back(candidate.centroid_m);
    footprints.push_back(candidate.footprint_m);
  }

  // The scene model: world up, the table, then which other candidates are support planes.
  const Eigen::Vector3f camera_up(0.0F, -1.0F, 0.0F);
  const int dominant = up_ ? dominant_horizontal(models, *up_, horizontal_max_deg_)
                           : dominant_horizontal(models, camera_up, up_prior_max_deg_);
  Eigen::Vector3f up = up_.value_or(camera_up);
  if (!up_ && dominant >= 0) up = models[dominant].normal;
  const TableChoice table = dominant >= 0
                                ? choose_table(models, centroids, sizes, footprints,
                                               estimate_valid_px(xyz), up, table_rule_)
                                : TableChoice{-1, std::vector<CandidateRole>(models.size()), {}};
  const std::vector<CandidateEvidence> evidence =
      decide_support(xyz, models, table.table, table.roles, up, support_rule_);
  const AcceptedPlanes accepted =
      accepted_planes(candidates, table, evidence, up, support_rule_.min_cos_horizontal);

  auto planes = of_frame<SupportPlanes>(points);
  planes.up = up.cast<double>();
  cv::Mat plane_labels;
  // What is left for objects: patches minus plane points, minus segments too small to matter.
  cv::Mat remaining_labels;
  const PlaneAssignment assignment =
      assign_to_planes(labels, patches.count, xyz, accepted.models, accepted.roles, accepted.table,
                       assignment_rule_, plane_labels, remaining_labels);
  std::int32_t remaining_count = split_and_drop_left_patches(
      remaining_labels, patches.count, assignment, xyz, min_segment_px, cut_pieces_);
  std::int64_t flat_object_px = 0;
  if (accepted.table >= 0) {
    remaining_count = give_flat_objects_back(
        plane_labels, accepted.table + 1, remaining_labels, remaining_count, cut_pieces_, xyz,
        accepted.models[static_cast<std::size_t>(accepted.table)], flat_object_rule,
        flat_object_buffers_, flat_object_px);
  }

  for (std::size_t c = 0; c < accepted.models.size(); ++c) {
    Plane plane;
    plane.id = static_cast<std::int32_t>(c + 1);
    plane.normal = accepted.models[c].normal.cast<double>();
    plane.offset_m = accepted.models[c].offset_m;
    plane.inliers = assignment.inliers[c];
    if (static_cast<int>(c) == accepted.table) plane.inliers -= flat_object_px;
    plane.rms_m = assignment.rms_m[c];
    plane.horizontal = plane.normal.dot(planes.up) >= support_rule_.min_cos_horizontal;
    plane.role = accepted.roles[c];
    planes.planes.push_back(plane);
  }
  if (accepted.table >= 0) {
    // Every plane of the table's level outlines the table.
    std::vector<char> table_ids(accepted.models.size() + 1, 0);
    for (std::size_t c = 0; c < accepted.models.size(); ++c)
      table_ids[c + 1] = accepted.roles[c] == PlaneRole::table;
    planes.table_id = accepted.table + 1;
    planes.table_outline_m = table_outline(
        plane_labels, labels, table_patches(assignment, accepted.roles), xyz, table_ids,
        accepted.models[static_cast<std::size_t>(accepted.table)], up, kOutlineStridePx);
  }

  if (assignment.valid_px == 0) {
    ctx.warn("no valid points: no planes");
  } else if (planes.planes.empty()) {
    ctx.warn("no support plane found: every patch is left for objects");
  }
  ctx.metric("planes", static_cast<double>(planes.planes.size()));
  ctx.metric("flat_object_px", static_cast<double>(flat_object_px));
  ctx.metric("plane_ratio", assignment.valid_px > 0
                                ? static_cast<double>(assignment.plane_px - flat_object_px) /
                                      static_cast<double>(assignment.valid_px)
                                : 0.0);
  const auto plane_count = static_cast<std::int32_t>(planes.planes.size());
  kPlanes(ctx, std::move(planes));
  kPlaneLabels(ctx, LabelImage::make(points, std::move(plane_labels), plane_count));
  LabelImage remaining = LabelImage::make(patches, std::move(remaining_labels), remaining_count);
  PatchAdjacency adjacency = algo::find_patch_contacts(remaining);
  kPatchesOut(ctx, std::move(remaining));
  kAdjacency(ctx, std::move(adjacency));
}

// A patch that gave points to a plane and kept some may have kept several pieces (the table's
// patch run onto object tops through gaps in the edges): one patch each. Then the segments too
// small to matter go; slot 0 (no patch) is never kept. Returns the new patch count;
// `cut_pieces` marks the ids that are pieces of a patch a plane cut (for the flat-object rule).
std::int32_t SupportPlaneStage::split_and_drop_left_patches(
    cv::Mat& left_labels, std::int32_t patch_count, const PlaneAssignment& assignment,
    const cv::Mat& xyz, std::int64_t min_segment_px, std::vector<char>& cut_pieces) {
  auto* left = left_labels.ptr<std::int32_t>();
  const std::size_t total = left_labels.total();
  const std::size_t patch_slots = assignment.patch_px.size();
  std::vector<std::int64_t> left_px = assignment.left_px;
  std::int32_t count = patch_count;
  std::vector<char> cut(patch_slots, 0);
  bool any_cut = false;
  for (std::size_t slot = 1; slot < patch_slots; ++slot) {
    cut[slot] = left_px[slot] > 0 && left_px[slot] < assignment.patch_px[slot] ? 1 : 0;
    any_cut = any_cut || cut[slot] != 0;
  }
  if (any_cut) {
    count = pieces_.split(left_labels, patch_count, cut, xyz, split_gate_);
    cut.resize(static_cast<std::size_t>(count) + 1, 1);  // the new ids are pieces too
    left_px.assign(static_cast<std::size_t>(count) + 1, 0);
    algo::for_each_label_run(left, total, [&](std::int32_t id, std::size_t begin, std::size_t end) {
      left_px[static_cast<std::size_t>(id)] += static_cast<std::int64_t>(end - begin);
    });
  }
  const std::size_t left_slots = left_px.size();
  std::vector<char> too_small(left_slots, 0);
  bool small_segments = false;
  for (std::size_t slot = 1; slot < left_slots; ++slot) {
    const std::int64_t size = left_px[slot];
    too_small[slot] = size > 0 && size < min_segment_px;
    small_segments = small_segments || too_small[slot] != 0;
  }
  if (small_segments) {
    algo::for_each_label_run(left, total, [&](std::int32_t id, std::size_t begin, std::size_t end) {
      if (too_small[static_cast<std::size_t>(id)] != 0) std::fill(left + begin, left + end, 0);
    });
  }
  cut.resize(static_cast<std::size_t>(count) + 1, 0);
  cut_pieces = std::move(cut);
  return count;
}

}  // namespace facet::planes
