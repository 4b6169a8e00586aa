#include "io/output_folder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <system_error>

#include "facet/error.hpp"

namespace facet::io {

void ensure_folder(const std::filesystem::path& dir) {
  if (dir.empty()) throw StageError("param 'dir' is empty: set an output folder");
  if (dir.has_root_directory() && dir.relative_path().empty()) {
    throw StageError("param 'dir' is the filesystem root '" + dir.string() +
                     "': set an output folder");
  }
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    throw StageError("cannot create output folder '" + dir.string() +
                     "': " + (error ? error.message() : std::string("a file of that name exists")));
  }
}

EarlierResults EarlierResults::survey(const std::filesystem::path& dir,
                                      std::string_view extension) {
  EarlierResults earlier;
  earlier.dir_ = dir;
  earlier.extension_ = std::string(extension);
  std::error_code error;
  for (std::filesystem::directory_iterator it(dir, error), end; !error && it != end;
       it.increment(error)) {
    const std::filesystem::path& path = it->path();
    const std::string name = path.filename().string();
    if (name.empty() || name.front() == '.' || path.extension() != extension) continue;
    std::error_code type_error;
    if (it->is_regular_file(type_error)) ++earlier.files_;
  }
  return earlier;
}

void EarlierResults::warn_once(ProcessContext& ctx) {
  if (told_) return;
  told_ = true;
  if (files_ == 0) return;
  ctx.warn("output folder '" + dir_.string() + "' already held " + std::to_string(files_) + " " +
           extension_ + " file(s): this run's frames replace theirs, any others stay beside them");
}

namespace {

std::string system_reason() {
  return std::strerror(errno);
}

// Opens a new file next to `file` under a name nobody else uses; O_EXCL never follows a symlink.
int open_partial(const std::filesystem::path& file, std::filesystem::path& partial) {
  std::random_device entropy;
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name(1, '.');
    name.append(file.filename().string()).append(".partial-").append(std::to_string(entropy()));
    partial = file.parent_path() / name;
    const int fd = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file,
                           std::initializer_list<std::string_view> chunks) {
  std::filesystem::path partial;
  const int fd = open_partial(file, partial);
  if (fd < 0) {
    throw StageError("cannot write '" + file.string() + "': cannot create a file in '" +
                     file.parent_path().string() + "': " + system_reason());
  }
  bool written = true;
  for (const std::string_view chunk : chunks)
    written = written && write_all(fd, chunk);
  std::string reason = written ? std::string() : system_reason();
  // A full disk may show only when the file is closed.
  if (::close(fd) != 0 && written) {
    written = false;
    reason = system_reason();
  }
  if (written && std::rename(partial.c_str(), file.c_str()) != 0) {
    written = false;
    reason = system_reason();
  }
  if (!written) {
    ::unlink(partial.c_str());
    throw StageError("cannot write '" + file.string() + "': " + reason);
  }
}

std::filesystem::path frame_file(const std::filesystem::path& dir, const FrameInfo& frame) {
  if (!frame.stem.empty()) return dir / (frame.stem + ".png");
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06lld.png", static_cast<long long>(frame.index));
  return dir / name;
}

}  // namespace facet::io
