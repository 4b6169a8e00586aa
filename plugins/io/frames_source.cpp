#include "io/frames_source.hpp"

#include <opencv2/core.hpp>

#include "facet/contract.hpp"
#include "io/frame_listing.hpp"
#include "io/intrinsics_file.hpp"
#include "io/png_files.hpp"

namespace fs = std::filesystem;

namespace facet::io {
namespace {

const Out<DepthImage> kDepth{"depth",
                             "Depth, CV_16UC1 in mm (0 = invalid), with the frame index, "
                             "file stem, timestamp and camera intrinsics."};
const Out<LabelImage> kLabels{"labels",
                              "Ground-truth segment ids, CV_32SC1 (0 = background); an "
                              "empty packet for frames without a label file."};
const Param<std::string> kPath{
    "path",
    "data/mosd",
    "Dataset folder (depth/*.png, flat *-depth.png, or TUM associations.txt / "
    "depth.txt), a TUM list file, or a glob of depth PNGs (wildcards * and ? in the "
    "file name).",
    {.required = true}};
const Param<std::string> kIntrinsics{
    "intrinsics",
    "",
    "Intrinsics file (keys fx, fy, cx, cy, width, height); empty = "
    "<dataset folder>/intrinsics.yaml.",
    {.origin = "dataset format, see docs/data-formats.md"}};
const Param<std::string> kLabelsDir{
    "labels_dir",
    "label",
    "Folder of ground-truth label PNGs, relative to the dataset folder (or absolute); "
    "e.g. label_parts for part-level labels. A missing folder means no ground truth.",
    {.origin = "dataset format, see docs/data-formats.md"}};
const Param<double> kDepthScale{
    "depth_scale",
    0.0,
    "Depth PNG units per metre, converted to mm on reading (e.g. 10000 for "
    "YCB-Video's 0.1 mm); 0 = the layout's convention: 1000 (mm), TUM 5000.",
    {.unit = "1/m", .min = 0.0, .origin = "dataset format, see docs/data-formats.md"}};
const FilePlaybackParams kPlayback{{.item = "frame",
                                    .unusable = "unreadable, not 16-bit, wrong size",
                                    .timestamp_note = "TUM: from the list"}};

}  // namespace

StageSpec FramesSource::spec() {
  StageSpec spec("io.frames",
                 "Reads depth frames (and ground-truth labels) from a dataset folder.\n"
                 "A dataset folder DIR holds intrinsics.yaml, depth/*.png (16-bit, mm, "
                 "0 = invalid) and optionally label/*.png with the same stems. Frames are "
                 "read in natural order of their names (learn2 before learn10). Instead of a "
                 "folder, 'path' may be a glob of depth PNGs such as DIR/depth/learn*.png; "
                 "then DIR is the dataset folder. Two more layouts are read: a flat folder of "
                 "NNNNNN-depth.png (labels NNNNNN-label.png next to them, frame name NNNNNN), "
                 "and TUM RGB-D (a folder with associations.txt or depth.txt, or the list "
                 "itself: lines 'timestamp path'; the timestamps become the frames' "
                 "timestamps and depth is converted from 5000 units per metre to mm; "
                 "see 'depth_scale'). Ends the stream after the last frame "
                 "unless 'loop' is set. Reports the metric valid_ratio (valid pixels / all) and "
                 "warns about a frame without any valid pixel.");
  return spec.declare(kDepth, kLabels, kPath, kIntrinsics, kLabelsDir, kDepthScale, kPlayback)
      .concurrency(Concurrency::serial);
}

FramesSource::FramesSource(const Params& params)
    : path_(kPath(params)),
      intrinsics_param_(kIntrinsics(params)),
      labels_dir_param_(kLabelsDir(params)),
      depth_scale_(kDepthScale(params)),
      playback_(kPlayback(params)) {}

void FramesSource::open(const OpenContext& /*ctx*/) {
  listing_ = list_frames(path_);
  const FrameListing& listing = listing_;
  const fs::path intrinsics_file =
      intrinsics_param_.empty() ? listing.root / "intrinsics.yaml" : fs::path(intrinsics_param_);
  camera_ = read_intrinsics(intrinsics_file);

  playback_.schedule(listing.depth_files.size(), path_, "frames");
  schedule_.clear();
  for (const std::size_t index : playback_.scheduled())
    schedule_.push_back(listing.depth_files[index]);

  const fs::path labels_dir = fs::path(labels_dir_param_).is_absolute()
                                  ? fs::path(labels_dir_param_)
                                  : listing.root / labels_dir_param_;
  std::error_code error;
  labels_dir_ =
      !labels_dir_param_.empty() && fs::is_directory(labels_dir, error) ? labels_dir : fs::path();
}

void FramesSource::read_frame(std::size_t index, cv::Mat& depth, cv::Mat& labels) const {
  const fs::path& depth_file = listing_.depth_files[index];
  depth = depth_to_millimetres(read_depth_png(depth_file, camera_),
                               depth_scale_ > 0.0 ? depth_scale_ : listing_.depth_units_per_metre);
  // The flat layout pairs labels by name in the same folder; labels_dir "" still means none.
  const bool paired = !listing_.label_files.empty();
  if (labels_dir_param_.empty() || (!paired && labels_dir_.empty())) return;
  const fs::path label_file =
      paired ? listing_.label_files[index] : labels_dir_ / depth_file.filename();
  std::error_code error;
  if (!fs::exists(label_file, error)) return;
  labels = read_label_png(label_file, camera_);
}

void FramesSource::process(ProcessContext& ctx) {
  while (true) {
    const std::optional<std::size_t> next = playback_.next();
    if (!next) {
      ctx.end_of_stream();
      return;
    }
    const std::size_t index = *next;
    const fs::path& depth_file = listing_.depth_files[index];

    FrameHeader header;
    header.camera = camera_;
    header.frame.index = playback_.frame_index();
    header.frame.stem = listing_.stems[index];
    header.frame.stream_frames = playback_.stream_frames();
    header.frame.timestamp_ns = listing_.timestamps_ns.empty() ? playback_.nominal_timestamp_ns()
                                                               : listing_.timestamps_ns[index];
    cv::Mat depth;
    cv::Mat labels;  // stays empty when the frame has no labels
    try {
      read_frame(index, depth, labels);
    } catch (const StageError& error) {
      if (!playback_.skips_unusable()) throw;
      FilePlayback::warn_skipped(ctx, error);
      continue;
    }

    const double pixels = static_cast<double>(depth.total());
    const int valid_px = cv::countNonZero(depth);
    // Not an error (a sensor covered or pointed at the sky delivers such frames): the frame runs
    // through the graph, which finds nothing in it; the warning tells the user why.
    if (valid_px == 0) {
      ctx.warn("no valid depth in '" + depth_file.filename().string() + "': every pixel is 0");
    }
    ctx.metric("valid_ratio", static_cast<double>(valid_px) / pixels);
    kDepth(ctx, DepthImage::make(header, std::move(depth)));
    if (!labels.empty()) kLabels(ctx, LabelImage::counted(header, std::move(labels)));
    playback_.emitted();
    return;
  }
}

}  // namespace facet::io
