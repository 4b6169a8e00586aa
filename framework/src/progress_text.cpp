#include "facet/framework/progress_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace facet {
namespace {

// "0:04", "12:30", "1:02:03".
std::string clock_text(double seconds) {
  const auto total = static_cast<std::int64_t>(std::llround(std::max(0.0, seconds)));
  const std::int64_t hours = total / 3600;
  const std::int64_t minutes = total / 60 % 60;
  const std::int64_t secs = total % 60;
  if (hours > 0) return fmt::format("{}:{:02}:{:02}", hours, minutes, secs);
  return fmt::format("{}:{:02}", minutes, secs);
}

}  // namespace

std::int64_t expected_frames(const FrameEvent& event, std::int64_t max_frames) {
  if (event.stream_frames > 0 && max_frames >= 0) return std::min(event.stream_frames, max_frames);
  if (event.stream_frames > 0) return event.stream_frames;
  return std::max<std::int64_t>(max_frames, 0);
}

std::string progress_text(const FrameEvent& event, std::int64_t max_frames, double elapsed_s) {
  const std::int64_t done = event.index + 1;
  const std::int64_t total = expected_frames(event, max_frames);
  if (total <= 0 || done > total) {
    return fmt::format("frame {:>6}  {:<24}  {:7.2f} ms", done, event.stem, event.frame_ms);
  }
  const double left_s = elapsed_s / static_cast<double>(done) * static_cast<double>(total - done);
  const auto percent = static_cast<int>(100 * done / total);
  return fmt::format("frame {}/{}  {:>3}%  {:<24}  {:7.2f} ms  {} left", done, total, percent,
                     event.stem, event.frame_ms, clock_text(left_s));
}

}  // namespace facet
