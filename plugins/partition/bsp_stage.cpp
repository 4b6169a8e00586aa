#include "partition/bsp_stage.hpp"

#include <utility>

#include "facet/algo/pixel_scale.hpp"
#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "partition/object_labels.hpp"
#include "partition/partition_ports.hpp"

namespace facet::partition {
namespace {

const OptionalIn<PatchAdjacency> kAdjacency{
    "adjacency",
    "Not used; accepted so that partition.bsp and partition.convex are "
    "interchangeable in a graph."};
const Param<double> kToleranceM{
    "tolerance_m",
    0.012,
    "delta: points closer than this to a face's plane are on it.",
    {.unit = "m", .min = 0.0, .max = 1.0, .origin = "paper (delta = 12 mm)"}};
const Param<int> kMinSplitPx{
    "min_split_px",
    80,
    "N_split: a split needs this many points on each side (tolerates outliers of the "
    "plane fit). A pixel count at reference_area_px: it scales with the image area.",
    {.unit = "px", .min = 1.0, .max = 1.0e7, .origin = "paper: 20 at 320x240, x4 for 640x480"}};
const Param<int> kMinFacePx{
    "min_face_px",
    120,
    "N_f: least points of a patch to serve as a face, and least face points of a blob "
    "to be partitioned at all. A pixel count at reference_area_px: it scales with the image "
    "area.",
    {.unit = "px", .min = 3.0, .max = 1.0e7, .origin = "paper: 30 at 320x240, x4 for 640x480"}};
const Param<double> kMinFaceRatio{
    "min_face_ratio",
    0.1,
    "k_fe: a blob whose face points are fewer than this times its other points is one "
    "object (mostly edges: the faces say little about it).",
    {.min = 0.0, .max = 100.0, .origin = "paper (k_fe = 0.1)"}};
const Param<bool> kKeepPatches{
    "keep_patches",
    true,
    "Never cut a surface patch; it goes whole to the side holding most of its points. "
    "Fixes the split-order weakness (paper Fig. 9 right).",
    {.origin = "paper: announced fix"}};
const EnumParam<PlaneOwner> kPlaneOwner{
    "plane_owner",
    PlaneOwner::behind,
    {{PlaneOwner::boxes, "boxes"}, {PlaneOwner::behind, "behind"}},
    "Which side the on-plane points join: 'boxes' = the paper's bounding-box rule (eq. 5); "
    "'behind' = the side behind the face, where the body of a visible face lies (plane normals "
    "point towards the camera).",
    {.origin = "measured on the mOSD learn frames: F 0.954 (behind) vs 0.949 (boxes)"}};
const Param<int> kMaxSplits{"max_splits",
                            64,
                            "Most splits per blob; a guard against pathological input.",
                            {.min = 0.0, .max = 1.0e6}};

}  // namespace

StageSpec PartitionBsp::spec() {
  return StageSpec(
             "partition.bsp",
             "Binary space partitioning of blobs into objects by the planes of their faces.\n"
             "Per blob: faces are its patches with at least min_face_px points, each with a "
             "least-squares plane. A blob whose face points are fewer than min_face_px or than "
             "min_face_ratio times its other points stays one object. Otherwise faces are tried "
             "largest first: points further than tolerance_m behind / in front of the plane "
             "form the two sides; with at least min_split_px on each side the part is split, "
             "and the points on the plane join the side whose bounding box within 2 x "
             "tolerance_m of the plane is closest (L1 over both corners) to that of the "
             "on-plane points (eq. 5). The plane's side continues with its next face, the other "
             "side is partitioned in turn. With keep_patches a patch is never cut: it goes whole "
             "to the side holding most of its points. Blob pixels without a point take the "
             "object of the nearest pixel of their blob. Object ids follow the raster order of "
             "each object's first pixel.")
      .declare(kBlobs, kPatches, kAdjacency, kPoints, kObjects, kToleranceM, kMinSplitPx,
               kMinFacePx, kMinFaceRatio, kKeepPatches, kPlaneOwner, kMaxSplits,
               algo::kReferenceAreaParam)
      .concurrency(Concurrency::clonable);
}

PartitionBsp::PartitionBsp(const Params& params)
    : rule_{kToleranceM(params),  kMinSplitPx(params), kMinFacePx(params), kMinFaceRatio(params),
            kKeepPatches(params), kMaxSplits(params),  kPlaneOwner(params)},
      reference_area_px_(algo::kReferenceAreaParam(params)),
      partitioner_(rule_) {}

void PartitionBsp::process(ProcessContext& ctx) {
  const auto& blobs = kBlobs(ctx);
  const auto& patches = kPatches(ctx);
  const auto& points = kPoints(ctx);
  check_partition_inputs(blobs.labels, patches.labels, points.points);
  const algo::PixelScale scale(reference_area_px_, blobs.labels.size());
  BspRule rule = rule_;
  rule.min_split_px = scale.count(rule_.min_split_px);
  rule.min_face_px = scale.count(rule_.min_face_px, 3);
  partitioner_.set_rule(rule);
  segments_.build(blobs.labels, patches.labels, points.points);
  cv::Mat objects = cv::Mat::zeros(blobs.labels.size(), CV_32SC1);
  auto* labels = objects.ptr<std::int32_t>();
  partitioner_.reset_counters();
  std::int32_t next_id = 1;
  for (const BlobRange& blob : segments_.blobs) {
    next_id += partitioner_.partition(segments_, blob, labels, next_id);
  }
  fill_blob_gaps(objects, blobs.labels, next_id);
  const std::int32_t count = relabel_in_raster_order(objects);
  ctx.metric("objects", count);
  ctx.metric("splits", static_cast<double>(partitioner_.splits()));
  kObjects(ctx, LabelImage::make(blobs, std::move(objects), count));
}

}  // namespace facet::partition
