#pragma once
// How a recording source plays its files: which of them (start, stride), how often (loop), what
// an unusable one does (on_error) and the nominal timestamps (fps). io.frames and io.pcd share
// these rules; each source lists its files and reads one, the playback says which one is next.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/context.hpp"
#include "facet/contract.hpp"
#include "facet/error.hpp"
#include "facet/param.hpp"
#include "facet/stage_spec.hpp"

namespace facet::io {

// What the shared parameters' docs say of this source.
struct PlaybackWording {
  std::string item;            // what is played: "frame", "file"
  std::string unusable;        // examples of an unusable item, e.g. "unreadable, wrong size"
  std::string timestamp_note;  // after "timestamps are frame index / fps", e.g. "TUM: ..."
};

// What an unusable item does: fail stops the run, skip warns and goes on.
enum class OnError { fail, skip };

// What the playback parameters below say, as FilePlayback takes it.
struct PlaybackOptions {
  OnError on_error = OnError::fail;
  std::int64_t start = 0;
  std::int64_t stride = 1;
  bool loop = false;
  double fps_hz = 30.0;
};

// The on_error, start, stride, loop and fps parameters every file source shares, their docs
// worded for the source (each source defines its own kPlayback from its PlaybackWording):
// `spec.declare(kPlayback)` declares them, `kPlayback(params)` reads them.
struct FilePlaybackParams {
  explicit FilePlaybackParams(const PlaybackWording& wording);

  EnumParam<OnError> on_error;
  Param<std::int64_t> start;
  Param<std::int64_t> stride;
  Param<bool> loop;
  Param<double> fps;

  void declare_in(StageSpec& spec) const { spec.declare(on_error, start, stride, loop, fps); }
  PlaybackOptions operator()(const Params& params) const {
    return {on_error(params), start(params), stride(params), loop(params), fps(params)};
  }
};

class FilePlayback {
 public:
  explicit FilePlayback(const PlaybackOptions& options);

  // Schedules items start, start + stride, ... of `count` and rewinds. Throws StageError naming
  // `path` when start is beyond the last item.
  void schedule(std::size_t count, const std::string& path, const std::string& items);

  // The listing index of the next item to read, or nothing when the stream ends: after the last
  // item unless looping, and after a whole pass in which every item was skipped.
  std::optional<std::size_t> next();

  // on_error: whether an unusable item is skipped (else the read's StageError ends the run).
  bool skips_unusable() const { return skip_unusable_; }
  // Warns that the current item was skipped for `error`; the caller then asks for the next one.
  static void warn_skipped(ProcessContext& ctx, const StageError& error);

  // After a frame was output.
  void emitted();

  // Of the frame about to be output: its index in the stream and its nominal timestamp.
  std::int64_t frame_index() const { return emitted_; }
  std::int64_t nominal_timestamp_ns() const;
  // Frames the stream holds at most (skipped items make it fewer); 0 when looping (endless).
  std::int64_t stream_frames() const {
    return loop_ ? 0 : static_cast<std::int64_t>(schedule_.size());
  }

  const std::vector<std::size_t>& scheduled() const { return schedule_; }

 private:
  bool skip_unusable_;
  std::int64_t start_;
  std::int64_t stride_;
  bool loop_;
  double fps_hz_;

  std::vector<std::size_t> schedule_;  // listing indices, in playing order
  std::size_t next_ = 0;
  std::int64_t emitted_ = 0;
  std::int64_t emitted_in_pass_ = 0;
};

}  // namespace facet::io
