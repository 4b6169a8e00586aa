#include "track/track_labels.hpp"

#include <stdexcept>
#include <string>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace facet::track {
namespace {

const In<LabelImage> kLabelsIn{"labels", "Segment ids of the frame (0 = none), CV_32SC1."};
const Out<LabelImage> kLabelsOut{"labels",
                                 "The same segments with their track ids (0 = none); count = the "
                                 "largest id given so far."};
const EnumParam<eval::OverlapMeasure> kMeasure{
    "measure",
    eval::OverlapMeasure::mean_ratio,
    {{eval::OverlapMeasure::mean_ratio, "mean_ratio"}, {eval::OverlapMeasure::iou, "iou"}},
    "Overlap of a segment i and a track j: mean_ratio = (|i&j|/|i| + |i&j|/|j|) / 2, "
    "iou = |i&j| / |i|j|.",
    {.origin = "mean_ratio: the authors' later code"}};
const Param<double> kMinOverlap{
    "min_overlap",
    0.3,
    "A segment continues a track when their overlap is above this.",
    {.min = 0.0, .max = 1.0, .origin = "not tuned: well below the ~0.95 of a static scene"}};
const Param<std::int64_t> kMemoryFrames{
    "memory_frames",
    10,
    "Frames a lost track is remembered and can still be continued; 0 = forgotten the "
    "first frame it is not seen.",
    {.unit = "frames", .min = 0, .origin = "not tuned: 1/3 s at 30 Hz"}};

TrackOptions options_from(const Params& params) {
  TrackOptions options;
  options.measure = kMeasure(params);
  options.min_overlap = kMinOverlap(params);
  options.memory_frames = kMemoryFrames(params);
  return options;
}

}  // namespace

StageSpec TrackLabels::spec() {
  return StageSpec("track.labels",
                   "Keeps segment ids stable from frame to frame, so the objects of a video keep "
                   "their numbers. Each frame's segments are paired one to one with the tracks of "
                   "earlier frames by pixel overlap (Hungarian method, largest total overlap); a "
                   "segment paired with overlap above min_overlap takes the track's id, any other "
                   "starts a new track with an id never used before (ids only grow). A track that "
                   "finds no segment keeps the pixels it last had for memory_frames frames and can "
                   "be continued within them. Deterministic. Reports tracks (segments this frame), "
                   "new_tracks and remembered (tracks kept, seen or lost).")
      .declare(kLabelsIn, kLabelsOut, kMeasure, kMinOverlap, kMemoryFrames)
      .concurrency(Concurrency::serial);
}

TrackLabels::TrackLabels(const Params& params) : tracker_(options_from(params)) {}

void TrackLabels::process(ProcessContext& ctx) {
  const LabelImage& input = kLabelsIn(ctx);
  const std::int32_t largest_before = tracker_.largest_id();
  cv::Mat tracked_labels;
  try {
    tracked_labels = tracker_.update(input.labels);
  } catch (const std::invalid_argument& error) {
    throw StageError(std::string("input 'labels': ") + error.what());
  }
  LabelImage tracked = LabelImage::make(input, std::move(tracked_labels), tracker_.largest_id());
  double segments = 0.0;
  {
    std::vector<bool> seen(static_cast<std::size_t>(tracked.count) + 1, false);
    for (int y = 0; y < tracked.labels.rows; ++y) {
      const auto* row = tracked.labels.ptr<std::int32_t>(y);
      for (int x = 0; x < tracked.labels.cols; ++x) {
        if (row[x] != 0 && !seen[static_cast<std::size_t>(row[x])]) {
          seen[static_cast<std::size_t>(row[x])] = true;
          segments += 1.0;
        }
      }
    }
  }
  ctx.metric("tracks", segments);
  ctx.metric("new_tracks", static_cast<double>(tracker_.largest_id() - largest_before));
  ctx.metric("remembered", static_cast<double>(tracker_.remembered_tracks()));
  kLabelsOut(ctx, std::move(tracked));
}

}  // namespace facet::track
