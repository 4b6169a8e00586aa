#include "counter_source.hpp"

#include <facet/types/images.hpp>

namespace facet_template {

facet::StageSpec CounterSource::spec() {
  // Everything `facet inspect template.counter` prints and every graph is checked against.
  return facet::StageSpec("template.counter",
                          "Emits `frames` synthetic depth images, then ends the stream.\n"
                          "Depth ramps from `near` at the left column to `far` at the right.")
      .output<facet::DepthImage>("depth", "CV_16UC1 depth in millimetres.")
      .param("frames", 5, "Number of images before the end of the stream.", {.min = 0})
      .param("width", 64, "Image width.", {.unit = "px", .min = 2, .max = 4096})
      .param("height", 48, "Image height.", {.unit = "px", .min = 1, .max = 4096})
      .param("near", 500, "Depth of the left column.", {.unit = "mm", .min = 1, .max = 65535})
      .param("far", 2000, "Depth of the right column.", {.unit = "mm", .min = 1, .max = 65535})
      // A source keeps a position in its stream: frames must be produced one after another.
      .concurrency(facet::Concurrency::serial);
}

// Parameters arrive validated (type, range), so the constructor only converts them.
CounterSource::CounterSource(const facet::Params& params)
    : frames_(params.get_int("frames")),
      width_(static_cast<int>(params.get_int("width"))),
      height_(static_cast<int>(params.get_int("height"))),
      near_mm_(params.get_double("near")),
      far_mm_(params.get_double("far")) {}

void CounterSource::process(facet::ProcessContext& ctx) {
  if (emitted_ == frames_) {
    ctx.end_of_stream();  // a source says when it is done; outputs set now would be dropped
    return;
  }
  facet::DepthImage image;
  image.depth.create(height_, width_, CV_16UC1);
  for (int u = 0; u < width_; ++u) {
    const double t = static_cast<double>(u) / (width_ - 1);
    image.depth.col(u).setTo(cv::Scalar(near_mm_ + t * (far_mm_ - near_mm_)));
  }
  // Every image carries its frame and camera; downstream stages rely on them.
  image.frame.index = emitted_;
  image.frame.timestamp_ns = emitted_ * 33'333'333;  // a nominal 30 Hz
  image.frame.stem = "counter" + std::to_string(emitted_);
  image.camera = {.fx = 1.0 * width_,
                  .fy = 1.0 * width_,
                  .cx = 0.5 * width_,
                  .cy = 0.5 * height_,
                  .width = width_,
                  .height = height_};
  ctx.output("depth", std::move(image));
  ++emitted_;
}

}  // namespace facet_template
