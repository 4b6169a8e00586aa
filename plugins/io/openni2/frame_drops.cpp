#include "openni2/frame_drops.hpp"

namespace facet::openni2 {

std::int64_t FrameDrops::passed_on(std::int64_t device_index) {
  std::int64_t dropped = 0;
  if (last_index_ && device_index > *last_index_) dropped = device_index - *last_index_ - 1;
  last_index_ = device_index;
  total_ += dropped;
  unreported_ += dropped;
  ++frames_since_warning_;
  return dropped;
}

std::optional<std::string> FrameDrops::warning() {
  if (unreported_ == 0) return std::nullopt;
  if (warned_once_ && frames_since_warning_ < warn_every_) return std::nullopt;
  std::string text = std::to_string(unreported_) + " stale frame(s) dropped";
  text += warned_once_ ? " in the last " + std::to_string(frames_since_warning_) + " frames"
                       : " (the graph is slower than the camera)";
  text += "; " + std::to_string(total_) + " in all";
  warned_once_ = true;
  unreported_ = 0;
  frames_since_warning_ = 0;
  return text;
}

}  // namespace facet::openni2
