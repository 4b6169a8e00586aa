#include "eval/stability_eval.hpp"

#include <algorithm>
#include <numeric>

#include "facet/contract.hpp"
#include "facet/image_checks.hpp"
#include "facet/types/images.hpp"

namespace facet::eval {
namespace {

const In<LabelImage> kLabels{"labels", "Segment ids of the frame (0 = none), CV_32SC1."};
const OptionalIn<PointImage> kPoints{
    "points", "Points of the same size, for the centroid distance in mm (NaN = invalid)."};
const EnumParam<OverlapMeasure> kMeasure{
    "measure",
    OverlapMeasure::mean_ratio,
    {{OverlapMeasure::mean_ratio, "mean_ratio"}, {OverlapMeasure::iou, "iou"}},
    "Overlap of segments i and j: mean_ratio = (|i&j|/|i| + |i&j|/|j|) / 2, iou = "
    "|i&j| / |i|j|.",
    {.origin = "mean_ratio: the authors' later code; iou: the external scorer"}};
const Param<double> kMinOverlap{
    "min_overlap",
    0.0,
    "Paired segments correspond when their overlap is above this (0: any shared "
    "pixel).",
    {.min = 0.0, .max = 1.0}};

double mean_of(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

}  // namespace

StageSpec StabilityEval::spec() {
  return StageSpec(
             "eval.stability",
             "Frame-to-frame stability of a segmentation of a static scene (the paper's Table "
             "II). The segments of each frame and the frame before are paired one to one by "
             "overlap (Hungarian method, largest total overlap); paired segments that overlap "
             "by more than min_overlap correspond. Reports for every frame after the first: "
             "overlap_avg_pct and overlap_min_pct (overlap of corresponding segments), "
             "centroid_avg_px / centroid_max_px (pixel centroids) and, with points connected, "
             "centroid_avg_mm / centroid_max_mm (3D centroids of the valid points), segments, "
             "corresponding, spurious (segments without a counterpart in the frame before), "
             "spurious_pct (of segments), vanished (segments of the frame before without a "
             "counterpart), spurious_total (since the first frame) and compared (1; 0 for the "
             "first frame, which has nothing to compare with). Sequence figures: overlap avg = "
             "mean of overlap_avg_pct, min = min of overlap_min_pct, centroid max = max of "
             "centroid_max_mm, spurious abs = max of spurious_total, rel = mean spurious / mean "
             "segments. With measure iou it computes the external scorer's --stability figures. "
             "Label 0 is no segment. See docs/evaluation.md.")
      .declare(kLabels, kPoints, kMeasure, kMinOverlap)
      .concurrency(Concurrency::serial);
}

StabilityEval::StabilityEval(const Params& params) {
  options_.measure = kMeasure(params);
  options_.min_overlap = kMinOverlap(params);
}

void StabilityEval::process(ProcessContext& ctx) {
  const cv::Mat& labels = kLabels(ctx).labels;
  cv::Mat points;
  if (const PointImage* input = kPoints(ctx)) {
    points = input->points;
    require_same_size(labels, "labels", points, "points");
  }
  if (has_previous_) {
    require_same_size(labels, "labels", previous_labels_, "labels of the frame before");
    if (points.empty() != previous_points_.empty()) {
      throw StageError("input 'points': connected in one frame and empty in the next");
    }
  }
  if (!has_previous_) {
    ctx.metric("compared", 0.0);
  } else {
    const FrameStability frame =
        compare_frames(previous_labels_, previous_points_, labels, points, options_);
    spurious_total_ += frame.spurious;
    ctx.metric("compared", 1.0);
    ctx.metric("segments", static_cast<double>(frame.segments));
    ctx.metric("corresponding", static_cast<double>(frame.overlaps.size()));
    ctx.metric("spurious", static_cast<double>(frame.spurious));
    ctx.metric("spurious_pct", frame.segments > 0 ? 100.0 * static_cast<double>(frame.spurious) /
                                                        static_cast<double>(frame.segments)
                                                  : 0.0);
    ctx.metric("spurious_total", static_cast<double>(spurious_total_));
    ctx.metric("vanished", static_cast<double>(frame.vanished));
    if (!frame.overlaps.empty()) {
      ctx.metric("overlap_avg_pct", 100.0 * mean_of(frame.overlaps));
      ctx.metric("overlap_min_pct",
                 100.0 * *std::min_element(frame.overlaps.begin(), frame.overlaps.end()));
      ctx.metric("centroid_avg_px", mean_of(frame.centroid_px));
      ctx.metric("centroid_max_px",
                 *std::max_element(frame.centroid_px.begin(), frame.centroid_px.end()));
    }
    if (!frame.centroid_mm.empty()) {
      ctx.metric("centroid_avg_mm", mean_of(frame.centroid_mm));
      ctx.metric("centroid_max_mm",
                 *std::max_element(frame.centroid_mm.begin(), frame.centroid_mm.end()));
    }
  }
  previous_labels_ = labels;
  previous_points_ = points;
  has_previous_ = true;
}

}  // namespace facet::eval
