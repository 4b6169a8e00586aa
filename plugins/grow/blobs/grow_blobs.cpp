#include "blobs/grow_blobs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "blobs/blob_support.hpp"
#include "blobs/edge_attachment.hpp"
#include "blobs/euclidean_regions.hpp"
#include "blobs/workspace_box.hpp"
#include "facet/contract.hpp"
#include "facet/image_checks.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"

namespace facet::blobs {
namespace {

const In<LabelImage> kPatches{"patches",
                              "Patches left for objects (planes.support `patches`); 0 = not an "
                              "object candidate."};
const In<PointImage> kPoints{"points", "3D points, CV_32FC3 in metres, NaN = invalid; same size."};
const OptionalIn<SupportPlanes> kPlanes{
    "planes", "Support planes, for front_only and max_on_plane_fraction."};
const OptionalIn<LabelImage> kPlaneLabels{
    "plane_labels",
    "Which pixels are plane points (planes.support `plane_labels`, 0 = none); with "
    "edge_pixels, the valid pixels of no patch and no plane take part too."};
const Out<LabelImage> kBlobs{"blobs", "CV_32SC1 blob ids 1..count, 0 = no blob."};
const Param<double> kMaxDistance{
    "max_distance_m",
    0.01,
    "Delta_blob: neighbouring pixels join one blob when their points are closer.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "paper (10 mm; the authors' code used 15 mm)"}};
const Param<double> kDistanceGrowthStart{
    "distance_growth_start_m",
    1.2,
    "Beyond this depth max_distance_m grows with the square of the nearer point's "
    "depth, as a depth camera's depth steps do (a Kinect's: 3 mm at 1 m, 11 mm at 2 m, "
    "26 mm at 3 m): at 2.4 m it is 4 times max_distance_m. A fixed distance cuts far "
    "surfaces into one stripe per depth step. 0 = the same at every depth (the paper).",
    {.unit = "m",
     .min = 0.0,
     .max = 100.0,
     .origin = "measured on generated views 0.6-3.6 m away (docs/evaluation.md)"}};
const Param<std::int64_t> kMinSize{
    "min_size_px",
    200,
    "N_blob: smaller blobs are removed (not graspable). A pixel count at reference_area_px: it "
    "scales with the image area.",
    {.unit = "px", .min = 1.0, .max = 1.0e8, .origin = "paper: 50 at 320x240, x4"}};
const Param<double> kMinSizeReferenceDepth{
    "min_size_reference_depth_m",
    0.0,
    "Beyond this depth a blob needs only the area min_size_px covers here: a blob whose first "
    "pixel lies at depth z is kept with min_size_px * (reference / z)^2 pixels, and never fewer "
    "than min_size_far_px (grow.surfaces' rule, judged at the first pixel: a blob under "
    "min_size_px spans a few centimetres of depth). An object seen from twice as far covers a "
    "quarter of the pixels, so a fixed count drops the small objects of a far table that near "
    "ones of the same size keep. 0 = min_size_px at every depth (the paper).",
    {.unit = "m",
     .min = 0.0,
     .max = 20.0,
     .origin = "off: the paper's fixed count; 1.0 in graphs/tabletop.yaml, measured on the "
               "generated development sets (docs/evaluation.md)"}};
const Param<std::int64_t> kMinSizeFar{
    "min_size_far_px",
    50,
    "With min_size_reference_depth_m: the fewest pixels a far blob is kept with, however far. A "
    "pixel count at reference_area_px: it scales with the image area.",
    {.unit = "px",
     .min = 1.0,
     .max = 1.0e8,
     .origin = "grow.surfaces min_size_far_px in graphs/tabletop.yaml (docs/evaluation.md)"}};
const Param<bool> kFrontOnly{
    "front_only",
    true,
    "Remove blobs that lie behind a support plane (needs the planes input; without "
    "it nothing is removed).",
    {.origin = "measured: floor fragments past the table edge in uncropped views"}};
const Param<double> kMaxBehindFraction{
    "max_behind_fraction",
    0.5,
    "front_only: a blob with more than this share of its points behind one plane is "
    "removed.",
    {.min = 0.0, .max = 1.0, .origin = "majority"}};
const Param<double> kBehindMargin{
    "behind_margin_m",
    0.03,
    "front_only: how far behind a plane a point must be to count as behind it.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "planes.support behind_margin_m (measured: 2.5 delta)"}};
const Param<double> kMaxOnPlaneFraction{
    "max_on_plane_fraction",
    0.5,
    "With the planes input: a blob with more than this share of its points within "
    "on_plane_distance_m of a support plane is a shred of that plane (a strip of table "
    "cut off by an object's silhouette) and is removed. Above 1: never.",
    {.min = 0.0,
     .max = 2.0,
     .origin = "majority; needed since planes.support leaves object faces their "
               "points near the table"}};
const Param<double> kOnPlaneDistance{
    "on_plane_distance_m",
    0.012,
    "max_on_plane_fraction: how close to a plane a point counts as on it.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "planes.support distance_m (delta)"}};
const Param<bool> kOnTable{
    "on_table",
    true,
    "Scene model (docs/planes.md): when the planes name a table, objects stand on it: "
    "a blob must rise above the table and stand inside its outline.",
    {.origin = "docs/planes.md: the table, the structure around it, the objects"}};
const Param<double> kMinRise{
    "min_rise_m",
    0.006,
    "on_table and the plane band: a point more than this above the table (or another "
    "horizontal support) rises above it.",
    {.unit = "m", .min = 0.0, .max = 0.5, .origin = "planes.support min_object_height_m"}};
const Param<double> kMinRaisedFraction{
    "min_raised_fraction",
    0.5,
    "on_table: a blob with fewer than this share of its points above min_rise_m is "
    "not an object on the table (the table's front edge or underside, a shred of its "
    "top).",
    {.min = 0.0, .max = 1.0, .origin = "majority; measured on generated scenes"}};
const Param<double> kTableMargin{
    "table_margin_m",
    0.03,
    "on_table: the table's outline is grown by this much before a footprint is tested "
    "(objects at the table's visible border, the outline's sampling).",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "measured on generated scenes"}};
const Param<double> kMaxOutsideFraction{
    "max_outside_fraction",
    0.5,
    "on_table: a blob with more than this share of its footprint (its points projected "
    "onto the table plane) outside the grown outline stands beyond the table.",
    {.min = 0.0, .max = 1.0, .origin = "majority"}};
const Param<bool> kEdgePixels{
    "edge_pixels",
    true,
    "With the plane_labels input: valid pixels that are in no patch and on no plane "
    "(normal-edge pixels the patches did not absorb: silhouettes, creases, small "
    "curved objects whose every pixel is an edge) take part in the blobs too, as the "
    "paper's blobs hold edge pixels (k_fe counts them). Without it a small ball or "
    "cup rim that grew no patch is lost. They join the blob they connect to through "
    "other edge pixels (closer than max_distance_m, breadth first), never joining two "
    "blobs; those no blob reaches form blobs of their own (at least min_size_px) when a "
    "support plane was found.",
    {.origin = "paper sec. II-B e, f; measured in docs/evaluation.md"}};
const Param<Workspace> kWorkspace{
    "workspace",
    Workspace{},
    "Task space: blobs whose centroid lies outside this axis-aligned box are removed. "
    "'xmin,xmax,ymin,ymax,zmin,zmax' in metres in the camera frame (x right, y down, "
    "z forward), e.g. '-0.4,0.4,-0.5,0.3,0.5,1.2' for the reach of an arm; empty = "
    "no box.",
    {.origin = "none by default: the planes and the behind test handle uncropped "
               "views without it"}};

}  // namespace

StageSpec GrowBlobs::spec() {
  StageSpec spec(
      "grow.blobs",
      "Object blobs: Euclidean region growing of the points left after the planes.\n"
      "Paper sec. II-B e. Pixels of a non-zero patch with a valid point are linked to "
      "their 8 neighbours when the two points are closer than max_distance_m in 3D "
      "(single linkage); blobs under min_size_px are removed (with min_size_reference_depth_m, far "
      "blobs need fewer pixels: the same area). With the optional planes "
      "input, blobs with more than max_behind_fraction of their points over "
      "behind_margin_m behind a support plane (background seen beyond a table or "
      "through a wall opening; when front_only is set) or more than "
      "max_on_plane_fraction within on_plane_distance_m of one (a shred of the plane; "
      "points above a horizontal plane by more than min_rise_m are not on it: a book's "
      "top) are removed too. When the planes name a table (on_table): blobs that do not "
      "stand on it, with fewer than min_raised_fraction of their points min_rise_m above "
      "it (the table's front edge, its underside, the floor) or more than "
      "max_outside_fraction of their footprint outside the table's outline grown by "
      "table_margin_m (a chair, a wall's shreds beyond the table). With a workspace box, "
      "blobs whose centroid lies outside it. Ids 1..N follow the raster order of each "
      "blob's first pixel.");
  return spec
      .declare(kPatches, kPoints, kPlanes, kPlaneLabels, kBlobs, kMaxDistance, kDistanceGrowthStart,
               kMinSize, kMinSizeReferenceDepth, kMinSizeFar, kFrontOnly, kMaxBehindFraction,
               kBehindMargin, kMaxOnPlaneFraction, kOnPlaneDistance, kOnTable, kMinRise,
               kMinRaisedFraction, kTableMargin, kMaxOutsideFraction, kEdgePixels, kWorkspace,
               algo::kReferenceAreaParam)
      .concurrency(Concurrency::clonable);
}

GrowBlobs::GrowBlobs(const Params& params)
    : gate_(static_cast<float>(kMaxDistance(params)),
            static_cast<float>(kDistanceGrowthStart(params))),
      size_{kMinSize(params), kMinSizeReferenceDepth(params), kMinSizeFar(params)},
      reference_area_px_(algo::kReferenceAreaParam(params)),
      edge_pixels_(kEdgePixels(params)),
      workspace_(kWorkspace(params).box) {
  rule_.drop_behind = kFrontOnly(params);
  rule_.max_behind_fraction = kMaxBehindFraction(params);
  rule_.behind_margin_m = static_cast<float>(kBehindMargin(params));
  rule_.max_on_plane_fraction = kMaxOnPlaneFraction(params);
  rule_.on_plane_distance_m = static_cast<float>(kOnPlaneDistance(params));
  rule_.on_table = kOnTable(params);
  rule_.min_rise_m = static_cast<float>(kMinRise(params));
  rule_.min_raised_fraction = kMinRaisedFraction(params);
  rule_.table_margin_m = static_cast<float>(kTableMargin(params));
  rule_.max_outside_fraction = kMaxOutsideFraction(params);
}

namespace {

// One row of the masks: a patch pixel with a finite point takes part; with plane labels, a
// finite point of no patch and no plane is an edge pixel. Without branches (|v| <= max is false
// for NaN and infinity), so that the rows vectorise: the per-pixel tests with their early exits
// were most of the stage's own time.
constexpr float kLargestFloat = std::numeric_limits<float>::max();

inline unsigned finite_point(const float* __restrict xyz, int col) {
  return static_cast<unsigned>(std::abs(xyz[3 * col]) <= kLargestFloat) &
         static_cast<unsigned>(std::abs(xyz[3 * col + 1]) <= kLargestFloat) &
         static_cast<unsigned>(std::abs(xyz[3 * col + 2]) <= kLargestFloat);
}

__attribute__((target_clones("avx2", "default"))) void mark_patch_points(
    const float* __restrict xyz, const std::int32_t* __restrict label,
    unsigned char* __restrict out, int cols) {
  for (int col = 0; col < cols; ++col)
    out[col] =
        static_cast<unsigned char>(finite_point(xyz, col) & static_cast<unsigned>(label[col] > 0));
}

__attribute__((target_clones("avx2", "default"))) void mark_patch_and_edge_points(
    const float* __restrict xyz, const std::int32_t* __restrict label,
    const std::int32_t* __restrict plane, unsigned char* __restrict out,
    unsigned char* __restrict edge, int cols) {
  for (int col = 0; col < cols; ++col) {
    const unsigned valid = finite_point(xyz, col);
    out[col] = static_cast<unsigned char>(valid & static_cast<unsigned>(label[col] > 0));
    edge[col] = static_cast<unsigned char>(valid & static_cast<unsigned>(label[col] <= 0) &
                                           static_cast<unsigned>(plane[col] == 0));
  }
}

// Appends the raster indices of the row's edge pixels. They are few: blocks without one are
// passed after a test that vectorises.
void collect_edge_pixels(const unsigned char* edge, int row, int cols,
                         std::vector<std::int32_t>& edge_pixels) {
  constexpr int kBlockPx = 32;
  for (int begin = 0; begin < cols; begin += kBlockPx) {
    const int end = std::min(begin + kBlockPx, cols);
    unsigned any = 0;
    for (int col = begin; col < end; ++col)
      any |= edge[col];
    if (any == 0) continue;
    for (int col = begin; col < end; ++col) {
      if (edge[col] != 0) edge_pixels.push_back(row * cols + col);
    }
  }
}

}  // namespace

void GrowBlobs::process(ProcessContext& ctx) {
  const LabelImage& patches = kPatches(ctx);
  const PointImage& points = kPoints(ctx);
  require_same_size(patches.labels, "patches", points.points, "points");
  const cv::Mat& xyz = points.points;

  // Taking part: a patch pixel with a finite point; with edge_pixels, afterwards, the pixels of
  // no patch and no plane (edge_attachment.hpp says why not at once).
  const LabelImage* plane_labels = edge_pixels_ ? kPlaneLabels(ctx) : nullptr;
  if (plane_labels != nullptr) {
    require_same_size(plane_labels->labels, "plane_labels", points.points, "points");
  }
  cv::Mat mask(patches.labels.size(), CV_8UC1);
  cv::Mat edges;
  std::vector<std::int32_t> edge_pixels;  // raster indices of the edge pixels
  if (plane_labels != nullptr) edges.create(patches.labels.size(), CV_8UC1);
  for (int row = 0; row < mask.rows; ++row) {
    const auto* label = patches.labels.ptr<std::int32_t>(row);
    const auto* p = xyz.ptr<float>(row);
    auto* out = mask.ptr<unsigned char>(row);
    if (plane_labels == nullptr) {
      mark_patch_points(p, label, out, mask.cols);
      continue;
    }
    auto* edge = edges.ptr<unsigned char>(row);
    mark_patch_and_edge_points(p, label, plane_labels->labels.ptr<std::int32_t>(row), out, edge,
                               mask.cols);
    collect_edge_pixels(edge, row, mask.cols, edge_pixels);
  }
  const algo::RegionSizeRule size = size_.scaled(algo::PixelScale(reference_area_px_, xyz.size()));
  EuclideanRegions regions = grow_euclidean_regions(mask, xyz, gate_, size);
  const SupportPlanes* planes = kPlanes(ctx);
  EdgeAttachment attachment;
  if (plane_labels != nullptr) {
    // Blobs of edge pixels alone only where a support plane was found: without one, the edge
    // pixels are as likely the shreds of a surface seen edge-on that no patch could grow on
    // (a table seen from its own height) as objects.
    const bool have_plane = planes != nullptr && !planes->planes.empty();
    attachment =
        attach_edge_pixels(regions, edges, edge_pixels, xyz, gate_, have_plane ? &size : nullptr);
  }
  DroppedBlobs dropped;
  if (planes != nullptr) dropped = drop_background_blobs(regions, xyz, *planes, rule_);
  const std::int32_t outside = workspace_ ? drop_blobs_outside(regions, xyz, *workspace_) : 0;

  LabelImage blobs = LabelImage::make(points, std::move(regions.labels), regions.count);
  ctx.metric("blobs", blobs.count);
  ctx.metric("blobs_behind_planes", dropped.behind);
  ctx.metric("blobs_on_planes", dropped.on_plane);
  ctx.metric("blobs_not_raised", dropped.not_raised);
  ctx.metric("blobs_outside_table", dropped.outside_table);
  ctx.metric("blobs_outside_workspace", outside);
  if (plane_labels != nullptr) {
    ctx.metric("edge_px_attached", static_cast<double>(attachment.attached_px));
    ctx.metric("edge_only_blobs", attachment.edge_only_blobs);
  }
  kBlobs(ctx, std::move(blobs));
}

}  // namespace facet::blobs
