#include "grow/grow_surfaces.hpp"

#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <utility>

#include "facet/algo/patch_contacts.hpp"
#include "facet/algo/pixel_scale.hpp"
#include "facet/contract.hpp"
#include "facet/image_checks.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "grow/pixel_classes.hpp"
#include "grow/surface_regions.hpp"

namespace facet::grow {
namespace {

const In<EdgeImage> kEdges{"edges", "Edge decision; only `mask` is used (255 = edge)."};
const In<PointImage> kPoints{"points", "3D points, CV_32FC3 in metres, NaN = invalid; same size."};
const Out<LabelImage> kPatches{"patches",
                               "CV_32SC1 patch ids 1..count; 0 = invalid point, or edge/small-"
                               "region pixel that no patch claimed."};
const Out<PatchAdjacency> kAdjacency{"adjacency",
                                     "Pairs (a < b, sorted) of patches that touch (8-neighbours "
                                     "after assignment); contact_px = touching pixel pairs."};
const Param<int> kConnectivity{
    "connectivity",
    4,
    "Neighbourhood of the flood fill. 4 cannot leak through a one-pixel diagonal gap "
    "in an edge line; 8 joins diagonally touching pixels.",
    {.choices = {std::int64_t{4}, std::int64_t{8}},
     .origin = "authors' later code (their 2012 code used 8)"}};
const Param<std::int64_t> kMinSize{
    "min_size_px",
    100,
    "Regions smaller than this go back to the unassigned pool (noise between edges). "
    "A pixel count at reference_area_px: it scales with the image area.",
    {.unit = "px",
     .min = 1.0,
     .max = 1.0e7,
     .origin = "authors' later code: 25 px at 320x240, scaled x4 for 640x480"}};
const Param<double> kMinSizeReferenceDepth{
    "min_size_reference_depth_m",
    0.0,
    "Beyond this depth a region needs only the area min_size_px covers here: a region at mean "
    "depth z is kept with min_size_px * (reference / z)^2 pixels, and never fewer than "
    "min_size_far_px. A face seen from farther covers fewer pixels while the edge bands around it "
    "stay as wide, so a fixed count drops the faces of far objects that near ones of the same "
    "size keep. 0 = min_size_px at every depth.",
    {.unit = "m",
     .min = 0.0,
     .max = 20.0,
     .origin = "off: the authors' fixed count; 1.0 in graphs/tabletop.yaml, measured on the "
               "generated development sets (docs/evaluation.md)"}};
const Param<std::int64_t> kMinSizeFar{
    "min_size_far_px",
    50,
    "With min_size_reference_depth_m: the fewest pixels a far region is kept with, however far "
    "(below it, disparity noise between edges makes regions too). A pixel count at "
    "reference_area_px: it scales with the image area.",
    {.unit = "px",
     .min = 1.0,
     .max = 1.0e7,
     .origin = "measured on the generated development sets and mOSD (docs/evaluation.md): "
               "40-60 lie on one plateau of every set"}};
const Param<int> kAssignRadius{
    "assign_radius_px",
    5,
    "rho: the most steps (rounds) an unassigned pixel may be from a patch. The edge "
    "band around a crease is about (normal radius + edge pixels) = 5 px wide on each "
    "side whatever the resolution, so 5 reaches the band's middle from either side. 0 "
    "disables the assignment.",
    {.unit = "px", .min = 0.0, .max = 250.0, .origin = "authors' later code (rho = 5)"}};
const Param<double> kAssignMaxDistance{
    "assign_max_distance_m",
    0.01,
    "3D gate of each assignment step: a pixel only takes the label of a neighbour "
    "closer than this, so the two sides of a depth step keep to their own surfaces.",
    {.unit = "m",
     .min = 0.0,
     .max = 1.0,
     .origin = "authors' later code used 10-15 mm; 10 mm = the paper's blob distance "
               "(Delta_blob), the same neighbour-to-neighbour linkage"}};
const Param<double> kMaxUnassignedRatio{
    "max_unassigned_ratio",
    0.25,
    "Warn when more than this share of the valid pixels ends up in no patch.",
    {.min = 0.0,
     .max = 1.0,
     .origin = "measured: 0.004-0.06 on the bundled frames, 0.3-0.8 on noisy frames "
               "and grids of 2.5 cm boxes"}};

}  // namespace

StageSpec GrowSurfaces::spec() {
  StageSpec spec(
      "grow.surfaces",
      "Region growing of surface pixels into patches, then edge pixels join a patch.\n"
      "1. Flood fill: connected non-edge pixels with a valid point form a region; "
      "regions under min_size_px return to the unassigned pool (with "
      "min_size_reference_depth_m, far regions need fewer pixels: the same area). "
      "2. One assignment pass, breadth-first from the patches in rounds 1..assign_radius_px: in "
      "round r every unassigned pixel with a valid point that has an 8-neighbour labelled "
      "before round r takes the label of the neighbour nearest in 3D, if that neighbour is closer "
      "than assign_max_distance_m. A pixel thus joins the patch it is fewest steps from "
      "(within the (2*rho+1)^2 window), along steps that never jump a depth step. 3. Two "
      "patches are adjacent when a pixel of one has a pixel of the other among its 8 "
      "neighbours.\n"
      "Patch ids follow the raster order of each patch's first surface pixel (before "
      "step 2).");
  return spec
      .declare(kEdges, kPoints, kPatches, kAdjacency, kConnectivity, kMinSize,
               kMinSizeReferenceDepth, kMinSizeFar, kAssignRadius, kAssignMaxDistance,
               kMaxUnassignedRatio, algo::kReferenceAreaParam)
      .concurrency(Concurrency::clonable);
}

GrowSurfaces::GrowSurfaces(const Params& params)
    : connectivity_(kConnectivity(params)),
      region_size_{kMinSize(params), kMinSizeReferenceDepth(params), kMinSizeFar(params)},
      reference_area_px_(algo::kReferenceAreaParam(params)),
      max_unassigned_ratio_(kMaxUnassignedRatio(params)),
      assignment_(AssignmentRule{kAssignRadius(params), kAssignMaxDistance(params)}) {}

void GrowSurfaces::process(ProcessContext& ctx) {
  const EdgeImage& edges = kEdges(ctx);
  const PointImage& points = kPoints(ctx);
  require_same_size(edges.mask, "edges", points.points, "points");
  // The assignment reads images as flat arrays, which packet images are.
  const cv::Mat& xyz = points.points;

  // Surface = not an edge and a valid 3D point, so a patch never holds a pixel without a point,
  // whatever produced the edge mask.
  const cv::Mat classes = classify_pixels(edges.mask, xyz);
  const algo::PixelScale scale(reference_area_px_, xyz.size());
  SurfaceRegions regions = regions_.label(classes, xyz, connectivity_, region_size_.scaled(scale));
  const AssignmentResult assigned = assignment_.assign(regions.labels, classes, xyz);

  LabelImage patches = LabelImage::make(points, std::move(regions.labels), regions.count);
  PatchAdjacency adjacency = algo::find_patch_contacts(patches);

  const auto valid_px =
      static_cast<double>(regions.labelled_px + assigned.assigned_px + assigned.unassigned_px);
  ctx.metric("patches", patches.count);
  const double unassigned_ratio =
      valid_px > 0.0 ? static_cast<double>(assigned.unassigned_px) / valid_px : 0.0;
  ctx.metric("unassigned_ratio", unassigned_ratio);
  if (unassigned_ratio > max_unassigned_ratio_) {
    ctx.warn(std::to_string(std::lround(100.0 * unassigned_ratio)) +
             " % of the valid pixels are in no patch (more than max_unassigned_ratio): noisy "
             "depth, many holes (filter.median fill_holes), or surfaces smaller than "
             "min_size_px between edges (objects too small or too far away)");
  }
  kPatches(ctx, std::move(patches));
  kAdjacency(ctx, std::move(adjacency));
}

}  // namespace facet::grow
