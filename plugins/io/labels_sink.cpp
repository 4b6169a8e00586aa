#include "io/labels_sink.hpp"

#include <opencv2/core.hpp>

#include "facet/types/images.hpp"
#include "io/output_folder.hpp"
#include "io/png_files.hpp"

namespace facet::io {
namespace {

constexpr double kMaxPngLabel = 65535.0;  // the largest id a 16-bit PNG can hold

}  // namespace

StageSpec LabelsSink::spec() {
  return StageSpec("io.labels",
                   "Writes label images as <dir>/<stem>.png, 16-bit, 0 = background.\n"
                   "The same format as the ground truth io.frames reads, so results can be "
                   "scored and viewed with the same tools. Frames with an empty label packet "
                   "are not written. Fails on negative ids or ids above 65535.")
      .input<LabelImage>("labels", "Segment ids, CV_32SC1 (CV_16UC1 and CV_8UC1 accepted).")
      .param("dir", "out/labels", "Output folder, created if missing.", {.required = true})
      .concurrency(Concurrency::serial);
}

LabelsSink::LabelsSink(const Params& params) : dir_(params.get_string("dir")) {}

void LabelsSink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_);
}

void LabelsSink::process(ProcessContext& ctx) {
  if (!ctx.has_input("labels")) return;
  const auto& input = ctx.input<LabelImage>("labels");
  const cv::Mat& labels = input.labels;
  if (labels.empty()) return;
  const std::filesystem::path file = frame_file(dir_, input.frame);
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
  if (max_label > kMaxPngLabel) {
    throw StageError("cannot write '" + file.string() + "': label " +
                     std::to_string(static_cast<long long>(max_label)) +
                     " exceeds 65535, the largest id a 16-bit PNG can hold");
  }
  cv::Mat ids;
  labels.convertTo(ids, CV_16U);
  write_png(file, ids);
}

}  // namespace facet::io
