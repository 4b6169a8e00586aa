#include "io/frames_source.hpp"

#include <opencv2/core.hpp>

#include "io/frame_listing.hpp"
#include "io/intrinsics_file.hpp"
#include "io/png_files.hpp"

namespace fs = std::filesystem;

namespace facet::io {

StageSpec FramesSource::spec() {
  return StageSpec("io.frames",
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
                   "warns about a frame without any valid pixel.")
      .output<DepthImage>("depth",
                          "Depth, CV_16UC1 in mm (0 = invalid), with the frame index, "
                          "file stem, timestamp and camera intrinsics.")
      .output<LabelImage>("labels",
                          "Ground-truth segment ids, CV_32SC1 (0 = background); an "
                          "empty packet for frames without a label file.")
      .param("path", "data/mosd",
             "Dataset folder (depth/*.png, flat *-depth.png, or TUM associations.txt / "
             "depth.txt), a TUM list file, or a glob of depth PNGs (wildcards * and ? in the "
             "file name).",
             {.required = true})
      .param("intrinsics", "",
             "Intrinsics file (keys fx, fy, cx, cy, width, height); empty = "
             "<dataset folder>/intrinsics.yaml.",
             {.origin = "dataset format, see docs/data-formats.md"})
      .param("labels_dir", "label",
             "Folder of ground-truth label PNGs, relative to the dataset folder (or absolute); "
             "e.g. label_parts for part-level labels. A missing folder means no ground truth.",
             {.origin = "dataset format, see docs/data-formats.md"})
      .param("on_error", "fail",
             "What to do with an unusable frame (unreadable, not 16-bit, wrong size): fail "
             "stops the run with an error naming the file; skip warns and goes on.",
             {.choices = {std::string("fail"), std::string("skip")},
              .origin = "fail: a damaged recording should not pass unnoticed"})
      .param("start", 0, "Index of the first frame, in natural order.",
             {.unit = "frames", .min = 0.0})
      .param("stride", 1, "Read every stride-th frame from start on.",
             {.unit = "frames", .min = 1.0})
      .param("loop", false, "Start again from 'start' after the last frame instead of ending.")
      .param("depth_scale", 0.0,
             "Depth PNG units per metre, converted to mm on reading (e.g. 10000 for "
             "YCB-Video's 0.1 mm); 0 = the layout's convention: 1000 (mm), TUM 5000.",
             {.unit = "1/m", .min = 0.0, .origin = "dataset format, see docs/data-formats.md"})
      .param("fps", 30.0,
             "Nominal frame rate; timestamps are frame index / fps (TUM: from the list).",
             {.unit = "Hz",
              .min = 0.001,
              .max = 10000.0,
              .origin = "the 30 Hz of Kinect-type and Xtion depth cameras"})
      .concurrency(Concurrency::serial);
}

FramesSource::FramesSource(const Params& params)
    : path_(params.get_string("path")),
      intrinsics_param_(params.get_string("intrinsics")),
      labels_dir_param_(params.get_string("labels_dir")),
      on_error_(params.get_string("on_error") == "skip" ? OnError::skip : OnError::fail),
      start_(params.get_int("start")),
      stride_(params.get_int("stride")),
      loop_(params.get_bool("loop")),
      fps_hz_(params.get_double("fps")),
      depth_scale_(params.get_double("depth_scale")) {}

void FramesSource::open(const OpenContext& /*ctx*/) {
  listing_ = list_frames(path_);
  const FrameListing& listing = listing_;
  const fs::path intrinsics_file =
      intrinsics_param_.empty() ? listing.root / "intrinsics.yaml" : fs::path(intrinsics_param_);
  camera_ = read_intrinsics(intrinsics_file);

  const auto count = static_cast<std::int64_t>(listing.depth_files.size());
  if (start_ >= count) {
    throw StageError("param start=" + std::to_string(start_) + " but '" + path_ + "' has only " +
                     std::to_string(count) + " frames");
  }
  schedule_.clear();
  schedule_index_.clear();
  for (std::int64_t i = start_; i < count; i += stride_) {
    schedule_.push_back(listing.depth_files[static_cast<std::size_t>(i)]);
    schedule_index_.push_back(static_cast<std::size_t>(i));
  }

  const fs::path labels_dir = fs::path(labels_dir_param_).is_absolute()
                                  ? fs::path(labels_dir_param_)
                                  : listing.root / labels_dir_param_;
  std::error_code error;
  labels_dir_ =
      !labels_dir_param_.empty() && fs::is_directory(labels_dir, error) ? labels_dir : fs::path();
  next_ = 0;
  emitted_ = 0;
  emitted_in_pass_ = 0;
}

void FramesSource::read_frame(std::size_t index, DepthImage& depth, LabelImage& labels) const {
  const fs::path& depth_file = listing_.depth_files[index];
  depth.depth =
      depth_to_millimetres(read_depth_png(depth_file, camera_),
                           depth_scale_ > 0.0 ? depth_scale_ : listing_.depth_units_per_metre);
  // The flat layout pairs labels by name in the same folder; labels_dir "" still means none.
  const bool paired = !listing_.label_files.empty();
  if (labels_dir_param_.empty() || (!paired && labels_dir_.empty())) return;
  const fs::path label_file =
      paired ? listing_.label_files[index] : labels_dir_ / depth_file.filename();
  std::error_code error;
  if (!fs::exists(label_file, error)) return;
  labels.labels = read_label_png(label_file, camera_);
  double max_label = 0.0;
  cv::minMaxLoc(labels.labels, nullptr, &max_label);
  labels.count = static_cast<std::int32_t>(max_label);
}

void FramesSource::process(ProcessContext& ctx) {
  while (true) {
    if (next_ >= schedule_.size()) {
      // A pass in which every frame was skipped would loop forever: end instead.
      if (!loop_ || emitted_in_pass_ == 0) {
        ctx.end_of_stream();
        return;
      }
      next_ = 0;
      emitted_in_pass_ = 0;
    }
    const std::size_t index = schedule_index_[next_];
    const fs::path& depth_file = schedule_[next_++];

    FrameHeader header;
    header.camera = camera_;
    header.frame.index = emitted_;
    header.frame.stem = listing_.stems[index];
    header.frame.timestamp_ns =
        listing_.timestamps_ns.empty()
            ? static_cast<std::int64_t>(static_cast<double>(emitted_) * 1e9 / fps_hz_)
            : listing_.timestamps_ns[index];
    DepthImage depth{header, {}};
    LabelImage labels{header, {}, 0};
    try {
      read_frame(index, depth, labels);
    } catch (const StageError& error) {
      if (on_error_ == OnError::fail) throw;
      ctx.warn(std::string("skipped frame: ") + error.what());
      continue;
    }

    const double pixels = static_cast<double>(depth.depth.total());
    const int valid_px = cv::countNonZero(depth.depth);
    // Not an error (a sensor covered or pointed at the sky delivers such frames): the frame runs
    // through the graph, which finds nothing in it; the warning tells the user why.
    if (valid_px == 0) {
      ctx.warn("no valid depth in '" + depth_file.filename().string() + "': every pixel is 0");
    }
    ctx.metric("valid_ratio", static_cast<double>(valid_px) / pixels);
    ctx.output("depth", std::move(depth));
    if (!labels.labels.empty()) ctx.output("labels", std::move(labels));
    ++emitted_;
    ++emitted_in_pass_;
    return;
  }
}

}  // namespace facet::io
