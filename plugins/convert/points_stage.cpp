#include "convert/points_stage.hpp"

#include <stdexcept>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace facet::convert {

namespace {

const In<DepthImage> kDepth{"depth",
                            "Depth image with intrinsics, CV_16UC1 in mm (0 = invalid) or CV_32FC1 "
                            "in m (0 or NaN = invalid)."};
const Out<PointImage> kPoints{"points",
                              "CV_32FC3 points in metres, same size and header as the input; NaN "
                              "= invalid."};
const Param<double> kMinDepth{
    "min_depth_m",
    0.0,
    "Depths below this are treated as invalid (0 = no lower bound).",
    {.unit = "m",
     .min = 0.0,
     .max = 100.0,
     .origin = "no bound: keep every measured depth unless the graph restricts it"}};
const Param<double> kMaxDepth{
    "max_depth_m",
    0.0,
    "Depths above this are treated as invalid (0 = no upper bound).",
    {.unit = "m",
     .min = 0.0,
     .max = 100.0,
     .origin = "no bound: keep every measured depth unless the graph restricts it"}};

}  // namespace

StageSpec PointsStage::spec() {
  StageSpec spec("convert.points",
                 "Back-projects a depth image into organized 3D points.\n"
                 "Pixel (u, v) with depth Z becomes X = (u - cx) Z / fx, Y = (v - cy) Z / fy, Z, "
                 "in metres in the camera frame (x right, y down, z along the optical axis), "
                 "using the intrinsics carried by the depth image. Invalid depth (0 or NaN) "
                 "and depth outside [min_depth_m, max_depth_m] become NaN points; the image "
                 "keeps its size, so pixel neighbourhoods stay neighbourhoods.");
  return spec.declare(kDepth, kPoints, kMinDepth, kMaxDepth).concurrency(Concurrency::clonable);
}

PointsStage::PointsStage(const Params& params) : range_{kMinDepth(params), kMaxDepth(params)} {
  if (range_.max_m > 0.0 && range_.max_m < range_.min_m) {
    throw StageError("max_depth_m must not be below min_depth_m");
  }
}

void PointsStage::process(ProcessContext& ctx) {
  const DepthImage& input = kDepth(ctx);
  if (!input.camera.valid()) {
    throw StageError("the depth image carries no camera intrinsics (fx, fy, width, height)");
  }
  cv::Mat points;
  try {
    points = back_project(input.depth, input.camera, range_);
  } catch (const std::invalid_argument& error) {
    throw StageError(error.what());
  }
  kPoints(ctx, PointImage::make(input, std::move(points)));
}

}  // namespace facet::convert
