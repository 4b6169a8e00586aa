#include "io/dataset_images.hpp"

#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <string>

#include "facet/error.hpp"
#include "io/png_files.hpp"

namespace facet::io {
namespace {

constexpr double kMaxPngValue = std::numeric_limits<std::uint16_t>::max();

struct MillimetreImage {
  cv::Mat depth_mm;               // CV_16UC1
  std::int64_t out_of_range = 0;  // valid depths beyond 65.535 m, written as 0
};

// Metres to millimetres, rounded; invalid (NaN, 0, negative, infinite) becomes 0.
MillimetreImage to_millimetres(const cv::Mat& depth_m) {
  MillimetreImage result{cv::Mat(depth_m.size(), CV_16UC1), 0};
  for (int y = 0; y < depth_m.rows; ++y) {
    const auto* src = depth_m.ptr<float>(y);
    auto* dst = result.depth_mm.ptr<std::uint16_t>(y);
    for (int x = 0; x < depth_m.cols; ++x) {
      const double mm = std::round(static_cast<double>(src[x]) * 1000.0);
      const bool valid = std::isfinite(mm) && mm > 0.0;
      if (valid && mm > kMaxPngValue) ++result.out_of_range;
      dst[x] = valid && mm <= kMaxPngValue ? static_cast<std::uint16_t>(mm) : std::uint16_t{0};
    }
  }
  return result;
}

}  // namespace

std::int64_t write_depth_png(const std::filesystem::path& file, const cv::Mat& depth) {
  if (depth.type() == CV_16UC1) {
    write_png(file, depth);
    return 0;
  }
  if (depth.type() != CV_32FC1) {
    throw StageError("cannot write '" + file.string() +
                     "': depth must be CV_16UC1 (mm) or CV_32FC1 (m)");
  }
  const MillimetreImage converted = to_millimetres(depth);
  write_png(file, converted.depth_mm);
  return converted.out_of_range;
}

void write_depth_png(ProcessContext& ctx, const std::filesystem::path& file, const cv::Mat& depth) {
  const std::int64_t out_of_range = write_depth_png(file, depth);
  if (out_of_range > 0) {
    ctx.warn(std::to_string(out_of_range) + " pixels beyond 65.535 m written as 0 in '" +
             file.string() + "'");
  }
}

void write_label_png(const std::filesystem::path& file, const cv::Mat& labels) {
  if (labels.channels() != 1 ||
      (labels.depth() != CV_32S && labels.depth() != CV_16U && labels.depth() != CV_8U)) {
    throw StageError("cannot write '" + file.string() +
                     "': labels must be single-channel CV_32S, CV_16U or CV_8U");
  }
  double min_label = 0.0;
  double max_label = 0.0;
  cv::minMaxLoc(labels, &min_label, &max_label);
  if (min_label < 0.0) {
    throw StageError("cannot write '" + file.string() + "': negative label " +
                     std::to_string(static_cast<long long>(min_label)));
  }
  if (max_label > kMaxPngValue) {
    throw StageError("cannot write '" + file.string() + "': label " +
                     std::to_string(static_cast<long long>(max_label)) +
                     " exceeds 65535, the largest id a 16-bit PNG can hold");
  }
  cv::Mat ids;
  labels.convertTo(ids, CV_16U);
  // Rows of label images are runs of one id: the run coder is several times faster than a
  // general deflater on them, at about the same size.
  write_png(file, ids, {.deflate = png::Deflate::runs});
}

}  // namespace facet::io
