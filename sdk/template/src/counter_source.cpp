#include "counter_source.hpp"

#include <cstdint>
#include <facet/contract.hpp>
#include <facet/types/images.hpp>

namespace facet_template {

namespace {

const facet::Out<facet::DepthImage> kDepth{"depth", "CV_16UC1 depth in millimetres."};
const facet::Param<std::int64_t> kFrames{
    "frames", 5, "Number of images before the end of the stream.", {.min = 0}};
const facet::Param<int> kWidth{"width", 64, "Image width.", {.unit = "px", .min = 2, .max = 4096}};
const facet::Param<int> kHeight{
    "height", 48, "Image height.", {.unit = "px", .min = 1, .max = 4096}};
const facet::Param<int> kNearMm{
    "near", 500, "Depth of the left column.", {.unit = "mm", .min = 1, .max = 65535}};
const facet::Param<int> kFarMm{
    "far", 2000, "Depth of the right column.", {.unit = "mm", .min = 1, .max = 65535}};

}  // namespace

facet::StageSpec CounterSource::spec() {
  // Everything `facet inspect template.counter` prints and every graph is checked against.
  facet::StageSpec spec("template.counter",
                        "Emits `frames` synthetic depth images, then ends the stream.\n"
                        "Depth ramps from `near` at the left column to `far` at the right.");
  return spec
      .declare(kDepth, kFrames, kWidth, kHeight, kNearMm, kFarMm)
      // A source keeps a position in its stream: frames must be produced one after another.
      .concurrency(facet::Concurrency::serial);
}

// Parameters arrive validated (type, range), so the constructor only reads them.
CounterSource::CounterSource(const facet::Params& params)
    : frames_(kFrames(params)),
      width_(kWidth(params)),
      height_(kHeight(params)),
      near_mm_(kNearMm(params)),
      far_mm_(kFarMm(params)) {}

void CounterSource::process(facet::ProcessContext& ctx) {
  if (emitted_ == frames_) {
    ctx.end_of_stream();  // a source says when it is done; outputs set now would be dropped
    return;
  }
  cv::Mat depth_mm(height_, width_, CV_16UC1);
  for (int u = 0; u < width_; ++u) {
    const double t = static_cast<double>(u) / (width_ - 1);
    depth_mm.col(u).setTo(cv::Scalar(near_mm_ + t * (far_mm_ - near_mm_)));
  }
  // Every image carries its frame and camera; downstream stages rely on them. A stage that
  // computes an image from an input passes the input as the header: Image::make(input, pixels).
  facet::FrameHeader header;
  header.frame.index = emitted_;
  header.frame.timestamp_ns = emitted_ * 33'333'333;  // a nominal 30 Hz
  header.frame.stem = "counter" + std::to_string(emitted_);
  header.camera = {.fx = 1.0 * width_,
                   .fy = 1.0 * width_,
                   .cx = 0.5 * width_,
                   .cy = 0.5 * height_,
                   .width = width_,
                   .height = height_};
  // make() checks the format the type promises (CV_16UC1 or CV_32FC1, continuous, the camera's
  // size) and throws std::invalid_argument saying what is wrong.
  kDepth(ctx, facet::DepthImage::make(header, std::move(depth_mm)));
  ++emitted_;
}

}  // namespace facet_template
