#include "openni2/oni_sink.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <system_error>
#include <utility>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace fs = std::filesystem;

namespace facet::openni2 {
namespace {

const In<DepthImage> kDepth{"depth", "Depth, CV_16UC1 in mm, at most 1600x1200 pixels."};
const Param<std::string> kPath{
    "path", "", "The .oni file to write (its folder is created).", {.required = true}};
const Param<int> kFps{"fps",
                      30,
                      "Frame rate the recording declares; also the period for timestamps "
                      "that do not grow.",
                      {.unit = "Hz", .min = 1, .max = 1000}};

}  // namespace

double horizontal_fov_rad(const CameraIntrinsics& camera) {
  return camera.fx > 0.0 ? 2.0 * std::atan(0.5 * camera.width / camera.fx) : 0.0;
}

double vertical_fov_rad(const CameraIntrinsics& camera) {
  return camera.fy > 0.0 ? 2.0 * std::atan(0.5 * camera.height / camera.fy) : 0.0;
}

StageSpec OniSink::spec() {
  StageSpec spec("io.oni",
                 "Writes the depth stream as one .oni recording (see docs/cameras.md).\n"
                 "OpenNI2's file format with one uncompressed depth stream in 1 mm: io.openni2 "
                 "(uri: the file) and other programs that use OpenNI2's file driver play it. The "
                 "first frame "
                 "fixes the image size and the field of view the file reports (from its "
                 "intrinsics: 2 atan(width / 2 fx) across); every later frame must have that "
                 "size. Each frame keeps its own timestamp (microseconds); one that does not "
                 "grow (a looping source) is replaced by the previous one plus a period of "
                 "'fps'. The file is complete when the stream ends.");
  return spec.declare(kDepth, kPath, kFps).concurrency(Concurrency::serial);
}

OniSink::OniSink(const Params& params) : file_(kPath(params)), fps_(kFps(params)) {}

OniSink::~OniSink() = default;

void OniSink::process(ProcessContext& ctx) {
  const DepthImage& depth = kDepth(ctx);
  if (!depth.in_millimetres()) {
    throw StageError("cannot record '" + file_.string() +
                     "': io.oni writes CV_16UC1 depth in mm (add a conversion before it)");
  }
  if (!writer_) {
    std::error_code error;
    if (file_.has_parent_path()) fs::create_directories(file_.parent_path(), error);
    if (error) {
      throw StageError("cannot record '" + file_.string() + "': cannot create folder '" +
                       file_.parent_path().string() + "': " + error.message());
    }
    OniStreamInfo info;
    info.width_px = depth.depth.cols;
    info.height_px = depth.depth.rows;
    info.fps = fps_;
    info.hfov_rad = horizontal_fov_rad(depth.camera);
    info.vfov_rad = vertical_fov_rad(depth.camera);
    if (info.hfov_rad <= 0.0) {
      std::string warning = "'";  // (built by appending: GCC 12 warns about "'" + string)
      warning += file_.string();
      warning += "': the frames carry no intrinsics; the recording has no field of view (its ";
      warning += "players need fx, fy given)";
      ctx.warn(std::move(warning));
    }
    writer_ = std::make_unique<OniDepthWriter>(file_, info);
  }
  const std::int64_t period_us = 1'000'000 / fps_;
  std::int64_t timestamp_us = depth.frame.timestamp_ns / 1000;
  if (timestamp_us <= last_us_) timestamp_us = last_us_ + period_us;
  writer_->add(depth.depth, static_cast<std::uint64_t>(std::max<std::int64_t>(0, timestamp_us)));
  last_us_ = std::max<std::int64_t>(0, timestamp_us);
  ctx.metric("frames_written", static_cast<double>(writer_->frames()));
}

void OniSink::close() {
  if (writer_) {
    auto writer = std::move(writer_);
    writer->finish();  // throws naming the file on a write error
  }
}

}  // namespace facet::openni2
