#include "io/depth_sink.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "facet/types/images.hpp"
#include "io/output_folder.hpp"
#include "io/png_files.hpp"

namespace facet::io {
namespace {

struct MillimetreImage {
  cv::Mat depth_mm;               // CV_16UC1
  std::int64_t out_of_range = 0;  // valid depths beyond 65.535 m, written as 0
};

// Metres to millimetres, rounded; invalid (NaN, 0, negative, infinite) becomes 0.
MillimetreImage to_millimetres(const cv::Mat& depth_m) {
  MillimetreImage result{cv::Mat(depth_m.size(), CV_16UC1), 0};
  constexpr double kMaxMm = std::numeric_limits<std::uint16_t>::max();
  for (int y = 0; y < depth_m.rows; ++y) {
    const auto* src = depth_m.ptr<float>(y);
    auto* dst = result.depth_mm.ptr<std::uint16_t>(y);
    for (int x = 0; x < depth_m.cols; ++x) {
      const double mm = std::round(static_cast<double>(src[x]) * 1000.0);
      const bool valid = std::isfinite(mm) && mm > 0.0;
      if (valid && mm > kMaxMm) ++result.out_of_range;
      dst[x] = valid && mm <= kMaxMm ? static_cast<std::uint16_t>(mm) : std::uint16_t{0};
    }
  }
  return result;
}

}  // namespace

StageSpec DepthSink::spec() {
  return StageSpec("io.depth",
                   "Writes depth images as <dir>/<stem>.png, 16-bit millimetres, 0 = invalid.\n"
                   "Float input in metres is rounded to millimetres; NaN and values that do not "
                   "fit 16 bits (beyond 65.535 m) are written as 0, the latter with a warning.")
      .input<DepthImage>("depth", "Depth, CV_16UC1 in mm or CV_32FC1 in m.")
      .param("dir", "out/depth", "Output folder, created if missing.", {.required = true})
      .concurrency(Concurrency::serial);
}

DepthSink::DepthSink(const Params& params) : dir_(params.get_string("dir")) {}

void DepthSink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_);
}

void DepthSink::process(ProcessContext& ctx) {
  const auto& input = ctx.input<DepthImage>("depth");
  const std::filesystem::path file = frame_file(dir_, input.frame);
  if (input.depth.type() == CV_16UC1) {
    write_png(file, input.depth);
    return;
  }
  if (input.depth.type() != CV_32FC1) {
    throw StageError("cannot write '" + file.string() +
                     "': depth must be CV_16UC1 (mm) or CV_32FC1 (m)");
  }
  const MillimetreImage converted = to_millimetres(input.depth);
  if (converted.out_of_range > 0) {
    ctx.warn(std::to_string(converted.out_of_range) + " pixels beyond 65.535 m written as 0 in '" +
             file.string() + "'");
  }
  write_png(file, converted.depth_mm);
}

}  // namespace facet::io
