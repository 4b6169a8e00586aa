#include "io/output_folder.hpp"

#include <cstdio>
#include <system_error>

#include "facet/error.hpp"

namespace facet::io {

void ensure_folder(const std::filesystem::path& dir) {
  if (dir.empty()) throw StageError("param 'dir' is empty: set an output folder");
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    throw StageError("cannot create output folder '" + dir.string() +
                     "': " + (error ? error.message() : std::string("a file of that name exists")));
  }
}

std::filesystem::path frame_file(const std::filesystem::path& dir, const FrameInfo& frame) {
  if (!frame.stem.empty()) return dir / (frame.stem + ".png");
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06lld.png", static_cast<long long>(frame.index));
  return dir / name;
}

}  // namespace facet::io
