#include "io/file_playback.hpp"

namespace facet::io {

FilePlaybackParams::FilePlaybackParams(const PlaybackWording& wording)
    : on_error{"on_error",
               OnError::fail,
               {{OnError::fail, "fail"}, {OnError::skip, "skip"}},
               "What to do with an unusable " + wording.item + " (" + wording.unusable +
                   "): fail stops the run with an error naming the file; skip warns and goes on.",
               {.origin = "fail: a damaged recording should not pass unnoticed"}},
      start{"start",
            0,
            "Index of the first " + wording.item + ", in natural order.",
            {.unit = "frames", .min = 0.0}},
      stride{"stride",
             1,
             "Read every stride-th " + wording.item + " from start on.",
             {.unit = "frames", .min = 1.0}},
      loop{"loop", false,
           "Start again from 'start' after the last " + wording.item + " instead of ending."},
      fps{"fps",
          30.0,
          "Nominal frame rate; timestamps are frame index / fps (" + wording.timestamp_note + ").",
          {.unit = "Hz",
           .min = 0.001,
           .max = 10000.0,
           .origin = "the 30 Hz of Kinect-type and Xtion depth cameras"}} {}

FilePlayback::FilePlayback(const PlaybackOptions& options)
    : skip_unusable_(options.on_error == OnError::skip),
      start_(options.start),
      stride_(options.stride),
      loop_(options.loop),
      fps_hz_(options.fps_hz) {}

void FilePlayback::schedule(std::size_t count, const std::string& path, const std::string& items) {
  if (start_ >= static_cast<std::int64_t>(count)) {
    throw StageError("param start=" + std::to_string(start_) + " but '" + path + "' has only " +
                     std::to_string(count) + " " + items);
  }
  schedule_.clear();
  for (auto i = static_cast<std::size_t>(start_); i < count; i += static_cast<std::size_t>(stride_))
    schedule_.push_back(i);
  next_ = 0;
  emitted_ = 0;
  emitted_in_pass_ = 0;
}

std::optional<std::size_t> FilePlayback::next() {
  if (next_ >= schedule_.size()) {
    // A pass in which every item was skipped would loop forever: end instead.
    if (!loop_ || emitted_in_pass_ == 0) return std::nullopt;
    next_ = 0;
    emitted_in_pass_ = 0;
  }
  return schedule_[next_++];
}

void FilePlayback::warn_skipped(ProcessContext& ctx, const StageError& error) {
  ctx.warn(std::string("skipped frame: ") + error.what());
}

void FilePlayback::emitted() {
  ++emitted_;
  ++emitted_in_pass_;
}

std::int64_t FilePlayback::nominal_timestamp_ns() const {
  return static_cast<std::int64_t>(static_cast<double>(emitted_) * 1e9 / fps_hz_);
}

}  // namespace facet::io
