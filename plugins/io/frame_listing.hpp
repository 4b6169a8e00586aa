#pragma once
// Finding the frames of a dataset: a dataset folder, or a glob of depth PNGs.

#include <filesystem>
#include <string>
#include <vector>

namespace facet::io {

struct FrameListing {
  // The dataset folder: where intrinsics.yaml and the label folders are looked up by default.
  // For a dataset folder DIR it is DIR; for a glob DIR/depth/*.png it is DIR.
  std::filesystem::path root;
  // Depth PNGs in natural order of their stems (learn2 before learn10).
  std::vector<std::filesystem::path> depth_files;
};

// True when `path` is a glob rather than a folder ('*' or '?' in it).
bool is_glob(const std::string& path);

// `path` is either a dataset folder DIR (frames are DIR/depth/*.png) or a glob whose wildcards
// are in the file name only (e.g. DIR/depth/learn*.png). Throws facet::StageError when the
// folder is missing or holds no frames.
FrameListing list_frames(const std::string& path);

// Shell-style match of a file name: '*' matches any run of characters, '?' one character.
bool wildcard_match(std::string_view pattern, std::string_view name);

}  // namespace facet::io
