#include "eval/normal_stability_eval.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "eval/normal_deviation.hpp"
#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace facet::eval {
namespace {

const In<NormalImage> kNormals{"normals", "Unit normals, CV_32FC3 (NaN = none)."};
const OptionalIn<LabelImage> kPlaneLabels{
    "plane_labels",
    "Plane ids (0 = none) of the same size, e.g. planes.support's plane_labels: the "
    "largest plane becomes the region."};
const Param<PixelRect> kRoi{
    "roi",
    PixelRect{},
    "The region, \"x, y, width, height\" in pixels (cut to the image); empty = the "
    "whole largest plane (then plane_labels must be connected).",
    {.unit = "px", .origin = "paper: a 10x10 patch of the table"}};

// The pixels of the plane id that holds the most pixels (the smaller id on a tie); all zero
// when there is no plane.
cv::Mat largest_plane(const cv::Mat& plane_labels) {
  std::map<std::int32_t, std::int64_t> counts;
  for (int y = 0; y < plane_labels.rows; ++y) {
    const auto* row = plane_labels.ptr<std::int32_t>(y);
    for (int x = 0; x < plane_labels.cols; ++x) {
      if (row[x] != 0) ++counts[row[x]];
    }
  }
  cv::Mat mask = cv::Mat::zeros(plane_labels.size(), CV_8UC1);
  if (counts.empty()) return mask;
  const auto largest = std::max_element(counts.begin(), counts.end(),
                                        [](auto& a, auto& b) { return a.second < b.second; });
  mask.setTo(255, plane_labels == largest->first);
  return mask;
}

}  // namespace

StageSpec NormalStabilityEval::spec() {
  return StageSpec(
             "eval.normal_stability",
             "Frame-to-frame angular deviation of surface normals on a static scene (the "
             "paper's Table I: a 10x10 patch of the table over 50 frames). Compares every "
             "frame's normals with the frame before at the pixels of the region where both are "
             "valid. The region is the roi rectangle; with plane_labels connected it is the "
             "largest plane of both frames, cut to the roi if one is given. Reports for every "
             "frame after the first: deviation_avg_deg, deviation_max_deg (over the region's "
             "points), points (compared) and compared (1; 0 for the first frame or a frame "
             "without a valid point in the region). Sequence figures: average = mean of "
             "deviation_avg_deg (exact when every frame compares the same points), maximum = "
             "max of deviation_max_deg. See docs/evaluation.md.")
      .declare(kNormals, kPlaneLabels, kRoi)
      .concurrency(Concurrency::serial);
}

NormalStabilityEval::NormalStabilityEval(const Params& params) : roi_(kRoi(params).rect) {}

cv::Mat NormalStabilityEval::region_of(ProcessContext& ctx, const cv::Size& size) const {
  cv::Mat region;
  if (const LabelImage* plane_labels = kPlaneLabels(ctx)) {
    const cv::Mat& planes = plane_labels->labels;
    if (planes.size() != size) {
      throw StageError("inputs 'normals' and 'plane_labels' differ in size");
    }
    region = largest_plane(planes);
  } else if (roi_.empty()) {
    throw StageError(
        "param 'roi' is empty and input 'plane_labels' is not connected: there is no region "
        "to compare (set roi to \"x, y, width, height\" or connect plane_labels)");
  } else {
    region = cv::Mat(size, CV_8UC1, cv::Scalar(255));
  }
  if (!roi_.empty()) {
    const cv::Rect inside = roi_ & cv::Rect(cv::Point(0, 0), size);
    if (inside.empty()) {
      throw StageError("param 'roi': the rectangle lies outside the " + std::to_string(size.width) +
                       "x" + std::to_string(size.height) + " image");
    }
    cv::Mat cut = cv::Mat::zeros(size, CV_8UC1);
    region(inside).copyTo(cut(inside));
    region = cut;
  }
  return region;
}

void NormalStabilityEval::process(ProcessContext& ctx) {
  const cv::Mat& normals = kNormals(ctx).normals;
  const cv::Mat region = region_of(ctx, normals.size());
  if (has_previous_ && previous_normals_.size() != normals.size()) {
    throw StageError("input 'normals': the size changed from one frame to the next");
  }
  std::vector<double> degrees;
  if (has_previous_) {
    cv::Mat both;
    cv::bitwise_and(region, previous_region_, both);
    degrees = angular_deviations_deg(previous_normals_, normals, both);
  }
  ctx.metric("compared", degrees.empty() ? 0.0 : 1.0);
  if (!degrees.empty()) {
    ctx.metric("points", static_cast<double>(degrees.size()));
    ctx.metric("deviation_avg_deg", std::accumulate(degrees.begin(), degrees.end(), 0.0) /
                                        static_cast<double>(degrees.size()));
    ctx.metric("deviation_max_deg", *std::max_element(degrees.begin(), degrees.end()));
  }
  previous_normals_ = normals;
  previous_region_ = region;
  has_previous_ = true;
}

}  // namespace facet::eval
