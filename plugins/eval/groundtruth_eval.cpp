#include "eval/groundtruth_eval.hpp"

#include <charconv>
#include <stdexcept>
#include <string>

#include "facet/contract.hpp"
#include "facet/error.hpp"
#include "facet/types/images.hpp"

namespace facet::eval {
namespace {

const In<LabelImage> kLabels{"labels", "Predicted segment ids (0 = unlabelled), any integer type."};
const OptionalIn<LabelImage> kTruth{
    "truth",
    "Ground-truth ids of the same size (0 = background), e.g. io.frames' labels; an "
    "empty packet (no label file for this frame) skips the frame."};
const Param<LabelIds> kTruthBackground{
    "truth_background", LabelIds{},
    "Truth ids treated as background besides 0, comma-separated (e.g. \"1\" for a "
    "table labelled 1); empty = only 0."};
const Param<std::int64_t> kMinTruthPixels{
    "min_truth_pixels",
    0,
    "Truth objects with fewer pixels are left out, their pixels ignored in both images.",
    {.unit = "px", .min = 0}};
const Param<double> kSegmentedF{
    "segmented_f",
    0.75,
    "Pair F-measure from which a matched object counts as segmented (objects_f75).",
    {.min = 0.0, .max = 1.0, .origin = "UOIS (Xie et al.), OSD"}};
const Param<double> kCover{
    "cover",
    0.2,
    "Share of an object's pixels a segment must hold to count as covering it "
    "(over- and under-segmentation).",
    {.min = 0.0, .max = 1.0, .origin = "UOIS (Xie et al.)"}};

}  // namespace

StageSpec GroundTruthEval::spec() {
  return StageSpec(
             "eval.groundtruth",
             "Scores predicted segments against ground-truth labels (overlap P/R/F).\n"
             "Ground-truth objects and predicted segments are matched one to one by IoU "
             "(Hungarian method); P = matched overlap / all predicted object pixels, R = matched "
             "overlap / all truth object pixels, F = 2PR/(P+R), as in the unseen-object "
             "segmentation literature (UOIS, OSD). Label 0 is background on both sides: truth "
             "background is not an object, but predicted pixels on it count against P. Reports "
             "per frame: precision, recall, f, objects_f75_ratio (objects whose matched pair has "
             "F >= segmented_f, of all truth objects), objects_f75, over_segmented (objects "
             "covered by 2+ segments), under_segmented (segments covering 2+ objects), "
             "merged_objects, matched, truth_objects, segments, mean_iou, and scored (1; 0 for "
             "a frame without truth, which is skipped, not an error). A frame with truth but no "
             "segment scores P=1, R=0, F=0; segments but no truth object P=0, R=1, F=0; neither "
             "P=R=F=1. See docs/compare.md.")
      .declare(kLabels, kTruth, kTruthBackground, kMinTruthPixels, kSegmentedF, kCover)
      .concurrency(Concurrency::reentrant);
}

GroundTruthEval::GroundTruthEval(const Params& params) {
  options_.truth_background = kTruthBackground(params).ids;
  options_.min_truth_pixels = kMinTruthPixels(params);
  options_.segmented_f = kSegmentedF(params);
  options_.cover = kCover(params);
}

void GroundTruthEval::process(ProcessContext& ctx) {
  const LabelImage* truth_input = kTruth(ctx);
  if (truth_input == nullptr) {
    ctx.metric("scored", 0.0);
    return;
  }
  const cv::Mat& truth = truth_input->labels;
  const cv::Mat& predicted = kLabels(ctx).labels;
  OverlapScores scores;
  try {
    scores = score_overlap(truth, predicted, options_);
  } catch (const std::invalid_argument& error) {
    throw StageError(std::string("inputs 'truth' and 'labels': ") + error.what());
  }
  ctx.metric("scored", 1.0);
  ctx.metric("precision", scores.precision);
  ctx.metric("recall", scores.recall);
  ctx.metric("f", scores.f);
  ctx.metric("objects_f75_ratio", scores.objects_segmented_ratio);
  ctx.metric("objects_f75", static_cast<double>(scores.objects_segmented));
  ctx.metric("over_segmented", static_cast<double>(scores.over_segmented));
  ctx.metric("under_segmented", static_cast<double>(scores.under_segmenting));
  ctx.metric("merged_objects", static_cast<double>(scores.merged_objects));
  ctx.metric("matched", static_cast<double>(scores.matched));
  ctx.metric("truth_objects", static_cast<double>(scores.truth_objects));
  ctx.metric("segments", static_cast<double>(scores.segments));
  ctx.metric("mean_iou", scores.mean_iou);
}

}  // namespace facet::eval

std::variant<facet::eval::LabelIds, std::string> facet::ParamTraits<facet::eval::LabelIds>::parse(
    std::string_view text) {
  eval::LabelIds labels;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string_view::npos) end = text.size();
    std::size_t first = start;
    std::size_t last = end;
    while (first < last && text[first] == ' ')
      ++first;
    while (last > first && text[last - 1] == ' ')
      --last;
    if (first < last) {
      std::int32_t value = 0;
      const auto [ptr, error] = std::from_chars(text.data() + first, text.data() + last, value);
      if (error != std::errc() || ptr != text.data() + last || value <= 0) {
        std::string why = "'";
        why.append(text.substr(first, last - first));
        why.append("' is not a positive label id (expected e.g. \"1\" or \"1, 4\")");
        return why;
      }
      labels.ids.insert(value);
    } else if (end < text.size()) {
      std::string why = "empty entry in '";
      why.append(text);
      why.append("'");
      return why;
    }
    start = end + 1;
  }
  return labels;
}

std::string facet::ParamTraits<facet::eval::LabelIds>::format(const eval::LabelIds& value) {
  std::string text;
  for (const std::int32_t id : value.ids) {
    if (!text.empty()) text += ", ";
    text += std::to_string(id);
  }
  return text;
}
