#include "convert/points_stage.hpp"

#include <stdexcept>

#include "facet/types/images.hpp"

namespace facet::convert {

StageSpec PointsStage::spec() {
  return StageSpec("convert.points",
                   "Back-projects a depth image into organized 3D points.\n"
                   "Pixel (u, v) with depth Z becomes X = (u - cx) Z / fx, Y = (v - cy) Z / fy, Z, "
                   "in metres in the camera frame (x right, y down, z along the optical axis), "
                   "using the intrinsics carried by the depth image. Invalid depth (0 or NaN) "
                   "and depth outside [min_depth_m, max_depth_m] become NaN points; the image "
                   "keeps its size, so pixel neighbourhoods stay neighbourhoods.")
      .input<DepthImage>("depth",
                         "Depth image with intrinsics, CV_16UC1 in mm (0 = invalid) or CV_32FC1 "
                         "in m (0 or NaN = invalid).")
      .output<PointImage>("points",
                          "CV_32FC3 points in metres, same size and header as the input; NaN = "
                          "invalid.")
      .param("min_depth_m", 0.0, "Depths below this are treated as invalid (0 = no lower bound).",
             {.unit = "m",
              .min = 0.0,
              .max = 100.0,
              .origin = "no bound: keep every measured depth unless the graph restricts it"})
      .param("max_depth_m", 0.0, "Depths above this are treated as invalid (0 = no upper bound).",
             {.unit = "m",
              .min = 0.0,
              .max = 100.0,
              .origin = "no bound: keep every measured depth unless the graph restricts it"})
      .concurrency(Concurrency::clonable);
}

PointsStage::PointsStage(const Params& params)
    : range_{params.get_double("min_depth_m"), params.get_double("max_depth_m")} {
  if (range_.max_m > 0.0 && range_.max_m < range_.min_m) {
    throw StageError("max_depth_m must not be below min_depth_m");
  }
}

void PointsStage::process(ProcessContext& ctx) {
  const auto& input = ctx.input<DepthImage>("depth");
  if (input.depth.empty()) throw StageError("input depth image is empty");
  if (!input.camera.valid()) {
    throw StageError("the depth image carries no camera intrinsics (fx, fy, width, height)");
  }
  PointImage output;
  static_cast<FrameHeader&>(output) = input;
  try {
    output.points = back_project(input.depth, input.camera, range_);
  } catch (const std::invalid_argument& error) {
    throw StageError(error.what());
  }
  ctx.output("points", std::move(output));
}

}  // namespace facet::convert
