#include "io/record_sink.hpp"

#include <string>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "io/dataset_images.hpp"
#include "io/intrinsics_file.hpp"
#include "io/output_folder.hpp"

namespace facet::io {
namespace {

const In<DepthImage> kDepth{"depth", "Depth, CV_16UC1 in mm or CV_32FC1 in m, with intrinsics."};
const OptionalIn<LabelImage> kLabels{"labels",
                                     "Ground truth (or any segment ids) to record "
                                     "beside the depth; empty packets are skipped."};
const Param<std::string> kDir{
    "dir", "out/recording", "Dataset folder, created if missing.", {.required = true}};

}  // namespace

StageSpec RecordSink::spec() {
  StageSpec spec(
      "io.record",
      "Records a depth stream in the dataset layout io.frames reads (docs/data-formats.md): "
      "<dir>/intrinsics.yaml from the first frame, <dir>/depth/<stem>.png (16-bit mm, 0 = "
      "invalid) and, when the labels input carries an image, <dir>/label/<stem>.png "
      "(16-bit ids). Frames without a stem are named frame_<index>. Replaying the folder "
      "with io.frames gives the same depth (to the millimetre), labels and intrinsics. "
      "All frames must share one camera; a frame with other intrinsics is an error.");
  return spec.declare(kDepth, kLabels, kDir).concurrency(Concurrency::serial);
}

RecordSink::RecordSink(const Params& params) : dir_(kDir(params)) {}

void RecordSink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_ / "depth");
  earlier_ = EarlierResults::survey(dir_ / "depth", ".png");
  camera_.reset();
  label_folder_ready_ = false;
}

void RecordSink::process(ProcessContext& ctx) {
  earlier_.warn_once(ctx);
  const DepthImage& depth = kDepth(ctx);
  const std::filesystem::path depth_file = frame_file(dir_ / "depth", depth.frame);
  if (!camera_) {
    write_intrinsics(dir_ / "intrinsics.yaml", depth.camera);
    camera_ = depth.camera;
  } else if (*camera_ != depth.camera) {
    throw StageError("cannot record '" + depth_file.string() +
                     "': its intrinsics differ from the first frame's, and a dataset folder "
                     "holds one camera");
  }
  write_depth_png(ctx, depth_file, depth.depth);
  const LabelImage* labels = kLabels(ctx);
  if (labels == nullptr || labels->labels.empty()) return;
  if (!label_folder_ready_) {
    ensure_folder(dir_ / "label");
    label_folder_ready_ = true;
  }
  write_label_png(frame_file(dir_ / "label", depth.frame), labels->labels);
}

}  // namespace facet::io
