#pragma once
// Counts the frames a live source never passed on, from the device's frame numbers, and decides
// when to say so. Plain arithmetic, no OpenNI2.

#include <cstdint>
#include <optional>
#include <string>

namespace facet::openni2 {

class FrameDrops {
 public:
  // `warn_every_frames`: at most one warning per this many frames passed on.
  explicit FrameDrops(std::int64_t warn_every_frames = 300) : warn_every_(warn_every_frames) {}

  // The device numbered the frame passed on `device_index`; returns how many frames since the
  // previous one were not passed on (stale frames the `latest` policy drained, or frames the
  // driver overwrote before they were read). A number that does not grow (a recording that
  // starts again) begins a new count without drops.
  std::int64_t passed_on(std::int64_t device_index);

  // The warning to give now, if any: the first drop at once, then at most one per
  // warn_every_frames frames, covering the drops since the last warning.
  std::optional<std::string> warning();

  std::int64_t total() const { return total_; }

 private:
  std::int64_t warn_every_;
  std::optional<std::int64_t> last_index_;
  std::int64_t total_ = 0;
  std::int64_t unreported_ = 0;
  std::int64_t frames_since_warning_ = 0;
  bool warned_once_ = false;
};

}  // namespace facet::openni2
