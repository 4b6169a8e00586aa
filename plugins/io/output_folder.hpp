#pragma once
// Where the sinks write: one PNG per frame in a folder they create.

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

#include "facet/types/frame.hpp"

namespace facet::io {

// Creates `dir` (and its parents) if needed; throws facet::StageError naming it on failure.
void ensure_folder(const std::filesystem::path& dir);

// Writes the concatenated `chunks` to `file` whole or not at all: into a new file of a temporary
// name in the same folder (created exclusively, so never through a symlink), renamed onto `file`
// once written and closed. A symlink named `file` is replaced, its target left untouched; nobody
// reading the folder meanwhile sees half a file; an interrupted run leaves at most a
// '.<name>.partial-*' file. Throws facet::StageError naming the file and the system's reason.
void write_file_atomically(const std::filesystem::path& file,
                           std::initializer_list<std::string_view> chunks);

// <dir>/<stem>.png, or <dir>/frame_<index>.png (index zero-padded to 6) for frames without stem.
std::filesystem::path frame_file(const std::filesystem::path& dir, const FrameInfo& frame);

}  // namespace facet::io
