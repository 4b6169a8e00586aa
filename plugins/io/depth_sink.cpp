#include "io/depth_sink.hpp"

#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "io/dataset_images.hpp"
#include "io/output_folder.hpp"

namespace facet::io {
namespace {

const In<DepthImage> kDepth{"depth", "Depth, CV_16UC1 in mm or CV_32FC1 in m."};
const Param<std::string> kDir{
    "dir", "out/depth", "Output folder, created if missing.", {.required = true}};

}  // namespace

StageSpec DepthSink::spec() {
  StageSpec spec("io.depth",
                 "Writes depth images as <dir>/<stem>.png, 16-bit millimetres, 0 = invalid.\n"
                 "Float input in metres is rounded to millimetres; NaN and values that do not "
                 "fit 16 bits (beyond 65.535 m) are written as 0, the latter with a warning.");
  return spec.declare(kDepth, kDir).concurrency(Concurrency::serial);
}

DepthSink::DepthSink(const Params& params) : dir_(kDir(params)) {}

void DepthSink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_);
  earlier_ = EarlierResults::survey(dir_, ".png");
}

void DepthSink::process(ProcessContext& ctx) {
  earlier_.warn_once(ctx);
  const DepthImage& input = kDepth(ctx);
  write_depth_png(ctx, frame_file(dir_, input.frame), input.depth);
}

}  // namespace facet::io
