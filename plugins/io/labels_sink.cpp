#include "io/labels_sink.hpp"

#include "facet/types/images.hpp"
#include "io/dataset_images.hpp"
#include "io/output_folder.hpp"

namespace facet::io {

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
  earlier_ = EarlierResults::survey(dir_, ".png");
}

void LabelsSink::process(ProcessContext& ctx) {
  earlier_.warn_once(ctx);
  if (!ctx.has_input("labels")) return;
  const auto& input = ctx.input<LabelImage>("labels");
  const cv::Mat& labels = input.labels;
  if (labels.empty()) return;
  write_label_png(frame_file(dir_, input.frame), labels);
}

}  // namespace facet::io
