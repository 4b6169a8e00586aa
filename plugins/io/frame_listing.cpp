#include "io/frame_listing.hpp"

#include <algorithm>
#include <system_error>

#include "facet/error.hpp"
#include "io/natural_order.hpp"

namespace fs = std::filesystem;

namespace facet::io {
namespace {

bool has_png_extension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".png";
}

template <class Keep>
std::vector<fs::path> regular_files(const fs::path& folder, Keep keep) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (entry.is_regular_file(error) && keep(entry.path())) files.push_back(entry.path());
  }
  if (error) {
    throw StageError("cannot list folder '" + folder.string() + "': " + error.message());
  }
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return natural_less(a.filename().string(), b.filename().string());
  });
  return files;
}

FrameListing list_glob(const std::string& pattern_path) {
  const fs::path pattern(pattern_path);
  const fs::path folder = pattern.has_parent_path() ? pattern.parent_path() : fs::path(".");
  if (is_glob(folder.string())) {
    throw StageError("path '" + pattern_path +
                     "': wildcards are supported in the file name only, not in folders");
  }
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw StageError("path '" + pattern_path + "': folder '" + folder.string() +
                     "' does not exist");
  }
  const std::string name_pattern = pattern.filename().string();
  FrameListing listing;
  listing.root = fs::absolute(folder, error).lexically_normal().parent_path();
  listing.depth_files = regular_files(folder, [&](const fs::path& file) {
    return wildcard_match(name_pattern, file.filename().string());
  });
  if (listing.depth_files.empty()) {
    throw StageError("path '" + pattern_path + "' matches no files");
  }
  return listing;
}

FrameListing list_folder(const std::string& folder_path) {
  const fs::path folder(folder_path);
  std::error_code error;
  if (!fs::exists(folder, error)) {
    throw StageError("dataset folder '" + folder_path + "' does not exist");
  }
  if (!fs::is_directory(folder, error)) {
    throw StageError("path '" + folder_path +
                     "' is not a folder (give a dataset folder, or a glob such as "
                     "'frames/*.png')");
  }
  const fs::path depth_folder = folder / "depth";
  if (!fs::is_directory(depth_folder, error)) {
    throw StageError("dataset folder '" + folder_path + "' has no depth/ folder (expected '" +
                     depth_folder.string() + "/*.png')");
  }
  FrameListing listing;
  listing.root = folder;
  listing.depth_files = regular_files(depth_folder, has_png_extension);
  if (listing.depth_files.empty()) {
    throw StageError("no frames: '" + depth_folder.string() + "' holds no .png files");
  }
  return listing;
}

}  // namespace

bool is_glob(const std::string& path) {
  return path.find_first_of("*?") != std::string::npos;
}

FrameListing list_frames(const std::string& path) {
  if (path.empty()) throw StageError("param 'path' is empty: set a dataset folder or a glob");
  return is_glob(path) ? list_glob(path) : list_folder(path);
}

// Iterative matcher with one backtrack point (the last '*'), linear in practice.
bool wildcard_match(std::string_view pattern, std::string_view name) {
  std::size_t p = 0;
  std::size_t n = 0;
  std::size_t star = std::string_view::npos;
  std::size_t star_n = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      star_n = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++star_n;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*')
    ++p;
  return p == pattern.size();
}

}  // namespace facet::io
