#pragma once
// Where the sinks write: one PNG per frame in a folder they create.

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

#include "facet/context.hpp"
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

// What an output folder held before the run. A run into a folder of earlier results replaces the
// files of its own frames and leaves the others, so the folder afterwards mixes two runs and
// nothing in it tells which file came from which; a sink says so once, on its first frame.
class EarlierResults {
 public:
  EarlierResults() = default;
  // Counts the files named *<extension> directly in `dir` (not the '.<name>.partial-*' leftovers
  // of an interrupted write, which are hidden).
  static EarlierResults survey(const std::filesystem::path& dir, std::string_view extension);

  std::int64_t files() const { return files_; }
  // On the first call only, and only when the folder held such files: a warning naming the
  // folder and the count.
  void warn_once(ProcessContext& ctx);

 private:
  std::filesystem::path dir_;
  std::string extension_;
  std::int64_t files_ = 0;
  bool told_ = false;
};

// <dir>/<stem>.png, or <dir>/frame_<index>.png (index zero-padded to 6) for frames without stem.
std::filesystem::path frame_file(const std::filesystem::path& dir, const FrameInfo& frame);

}  // namespace facet::io
