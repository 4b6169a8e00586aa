#pragma once
// The text of a run's one-line progress display, apart from the terminal that shows it.

#include <cstdint>
#include <string>

#include "facet/framework/executor.hpp"

namespace facet {

// Frames the run will take: the source's own count, cut by the run's frame limit (`max_frames`,
// negative for none); 0 when neither is known (a camera without a limit).
std::int64_t expected_frames(const FrameEvent& event, std::int64_t max_frames);

// "frame 12/45  27%  learn11    31.20 ms  0:04 left" after the 12th of 45 frames, with the time
// left extrapolated from `elapsed_s` since the run began; "frame 12  learn11    31.20 ms" when
// the number of frames is not known.
std::string progress_text(const FrameEvent& event, std::int64_t max_frames, double elapsed_s);

}  // namespace facet
