#include "io/labels_sink.hpp"

#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "io/dataset_images.hpp"
#include "io/output_folder.hpp"

namespace facet::io {
namespace {

const In<LabelImage> kLabels{"labels", "Segment ids, CV_32SC1, >= 0."};
const Param<std::string> kDir{
    "dir", "out/labels", "Output folder, created if missing.", {.required = true}};

}  // namespace

StageSpec LabelsSink::spec() {
  StageSpec spec("io.labels",
                 "Writes label images as <dir>/<stem>.png, 16-bit, 0 = background.\n"
                 "The same format as the ground truth io.frames reads, so results can be "
                 "scored and viewed with the same tools. Frames with an empty label packet "
                 "are not written. Fails on ids above 65535.");
  return spec.declare(kLabels, kDir).concurrency(Concurrency::serial);
}

LabelsSink::LabelsSink(const Params& params) : dir_(kDir(params)) {}

void LabelsSink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_);
  earlier_ = EarlierResults::survey(dir_, ".png");
}

void LabelsSink::process(ProcessContext& ctx) {
  earlier_.warn_once(ctx);
  if (kLabels.packet(ctx).empty()) return;
  const LabelImage& input = kLabels(ctx);
  write_label_png(frame_file(dir_, input.frame), input.labels);
}

}  // namespace facet::io
