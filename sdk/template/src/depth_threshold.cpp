#include "depth_threshold.hpp"

#include <facet/contract.hpp>
#include <facet/types/images.hpp>
#include <opencv2/core.hpp>

namespace facet_template {
namespace {

// Each port and parameter is declared once: the descriptor puts it in the spec and reads it back,
// so a name or type is never written twice (facet/contract.hpp).
const facet::In<facet::DepthImage> kDepth{"depth", "CV_16UC1 depth in millimetres."};
const facet::Out<facet::DepthImage> kKept{"depth", "The input with far pixels set to 0."};
const facet::Param<int> kMaxMm{
    "max_mm", 1250, "Farthest depth kept.", {.unit = "mm", .min = 0, .max = 65535}};

}  // namespace

facet::StageSpec DepthThreshold::spec() {
  facet::StageSpec spec("template.threshold",
                        "Sets depth beyond `max_mm` to 0 (no measurement).\n"
                        "Reports `kept_ratio`: the share of measured pixels that were kept.");
  return spec
      .declare(kDepth, kKept, kMaxMm)
      // No state between frames and process() only reads members: several frames may run
      // through one instance at once.
      .concurrency(facet::Concurrency::reentrant);
}

DepthThreshold::DepthThreshold(const facet::Params& params) : max_mm_(kMaxMm(params)) {}

void DepthThreshold::process(facet::ProcessContext& ctx) {
  const facet::DepthImage& input = kDepth(ctx);
  if (!input.in_millimetres()) {
    // StageError is for problems the user can fix; the executor adds node, stage and frame.
    throw facet::StageError("expects CV_16UC1 depth in millimetres");
  }
  // Packets are immutable: write a new image rather than the input's. make() gives it the
  // input's frame and camera.
  cv::Mat kept = input.depth.clone();
  kept.setTo(0, input.depth > max_mm_);

  const int measured = cv::countNonZero(input.depth);
  if (measured > 0) {
    ctx.metric("kept_ratio", static_cast<double>(cv::countNonZero(kept)) / measured);
  }
  kKept(ctx, facet::DepthImage::make(input, std::move(kept)));
}

}  // namespace facet_template
