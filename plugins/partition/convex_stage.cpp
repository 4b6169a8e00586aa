#include "partition/convex_stage.hpp"

#include <utility>

#include "facet/algo/pixel_scale.hpp"
#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "partition/object_labels.hpp"
#include "partition/partition_ports.hpp"

namespace facet::partition {
namespace {

const In<PatchAdjacency> kAdjacency{"adjacency", "Which patches touch (from grow.surfaces)."};
const Param<double> kToleranceM{
    "tolerance_m",
    0.01,
    "Points closer than this to the other patch's plane count as behind it (sensor "
    "noise, and the rounded edge where two faces meet).",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "measured on mOSD learn frames"}};
const Param<double> kMinBehindShare{
    "min_behind_share",
    0.9,
    "Least share of each patch's points not in front of the other's plane for a "
    "convex junction; below 1 so that outliers and curved patches still join.",
    {.min = 0.0, .max = 1.0, .origin = "measured on mOSD learn frames"}};
const Param<double> kMinAngleDeg{
    "min_angle_deg",
    30.0,
    "Patches whose normals differ by less meet at a step, never joined.",
    {.unit = "deg", .min = 0.0, .max = 180.0, .origin = "authors' later code (30 deg)"}};
const Param<int> kMinPatchPx{
    "min_patch_px",
    100,
    "Smaller patches have no reliable plane; they join an object as leftover pixels. "
    "A pixel count at reference_area_px: it scales with the image area.",
    {.unit = "px", .min = 3.0, .max = 1.0e7, .origin = "grow.surfaces' min_size_px"}};

}  // namespace

StageSpec PartitionConvex::spec() {
  return StageSpec(
             "partition.convex",
             "Objects as groups of adjacent patches that meet at convex junctions.\n"
             "Per blob: every patch with at least min_patch_px points gets a least-squares "
             "plane, normal towards the camera. Two adjacent patches of the blob are joined when "
             "their normals differ by at least min_angle_deg (closer normals are a step between "
             "two surfaces, not an edge of one body) and each has at least min_behind_share of "
             "its points not more than tolerance_m in front of the other's plane: each lies on "
             "its own side of the other, as the faces of one convex body do. Joined patches "
             "(union-find) are objects; the blob's other pixels (in no patch, small patches, no "
             "point) join the object they are fewest pixel steps from within the blob; a blob "
             "with no patch is one object. Object ids follow the raster order of each object's "
             "first pixel.")
      .declare(kBlobs, kPatches, kAdjacency, kPoints, kObjects, kToleranceM, kMinBehindShare,
               kMinAngleDeg, kMinPatchPx, algo::kReferenceAreaParam)
      .concurrency(Concurrency::clonable);
}

PartitionConvex::PartitionConvex(const Params& params)
    : rule_{kToleranceM(params), kMinBehindShare(params), kMinAngleDeg(params),
            kMinPatchPx(params)},
      reference_area_px_(algo::kReferenceAreaParam(params)),
      merger_(rule_) {}

void PartitionConvex::process(ProcessContext& ctx) {
  const auto& blobs = kBlobs(ctx);
  const auto& patches = kPatches(ctx);
  const auto& adjacency = kAdjacency(ctx);
  const auto& points = kPoints(ctx);
  check_partition_inputs(blobs.labels, patches.labels, points.points);
  ConvexRule rule = rule_;
  rule.min_patch_px =
      algo::PixelScale(reference_area_px_, blobs.labels.size()).count(rule_.min_patch_px, 3);
  merger_.set_rule(rule);
  segments_.build(blobs.labels, patches.labels, points.points);
  neighbours_.build(adjacency, segments_.max_patch);
  cv::Mat objects = cv::Mat::zeros(blobs.labels.size(), CV_32SC1);
  auto* labels = objects.ptr<std::int32_t>();
  merger_.reset_counters();
  std::int32_t next_id = 1;
  for (const BlobRange& blob : segments_.blobs) {
    next_id += merger_.merge(segments_, blob, neighbours_, labels, next_id);
  }
  fill_blob_gaps(objects, blobs.labels, next_id);
  const std::int32_t count = relabel_in_raster_order(objects);
  ctx.metric("objects", count);
  ctx.metric("merges", static_cast<double>(merger_.merges()));
  kObjects(ctx, LabelImage::make(blobs, std::move(objects), count));
}

}  // namespace facet::partition
