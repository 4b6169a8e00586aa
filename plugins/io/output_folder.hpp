#pragma once
// Where the sinks write: one PNG per frame in a folder they create.

#include <filesystem>
#include <string>

#include "facet/types/frame.hpp"

namespace facet::io {

// Creates `dir` (and its parents) if needed; throws facet::StageError naming it on failure.
void ensure_folder(const std::filesystem::path& dir);

// <dir>/<stem>.png, or <dir>/frame_<index>.png (index zero-padded to 6) for frames without stem.
std::filesystem::path frame_file(const std::filesystem::path& dir, const FrameInfo& frame);

}  // namespace facet::io
