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

class FilePlayback {
 public:
  // Declares on_error, start, stride, loop and fps on `spec`.
  static void declare_params(StageSpec& spec, const PlaybackWording& wording);

  explicit FilePlayback(const Params& params);

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
