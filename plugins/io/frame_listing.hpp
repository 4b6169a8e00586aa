#pragma once
// Finding the frames of a dataset: a dataset folder (depth/*.png), a flat folder
// (NNNNNN-depth.png), a TUM RGB-D folder or association list, or a glob of depth PNGs.

#include <cstdint>
#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

namespace facet::io {

enum class FrameLayout {
  dataset,  // DIR/depth/<stem>.png, labels in DIR/<labels_dir>/<stem>.png
  flat,     // DIR/<stem>-depth.png, labels in DIR/<stem>-label.png
  tum,      // TUM RGB-D: a list of "timestamp path" lines, depth 5000 units per metre
};

struct FrameListing {
  FrameLayout layout = FrameLayout::dataset;
  // The dataset folder: where intrinsics.yaml and the label folders are looked up by default.
  // For a dataset folder DIR it is DIR; for a glob DIR/depth/*.png it is DIR; for a flat folder
  // or a glob DIR/*-depth.png it is DIR; for a TUM list DIR/depth.txt it is DIR.
  std::filesystem::path root;
  // Depth PNGs in natural order of their stems (learn2 before learn10); for TUM in list order.
  std::vector<std::filesystem::path> depth_files;
  // Per depth file: the frame's name (the file stem, without "-depth" in the flat layout).
  std::vector<std::string> stems;
  // Per depth file, flat layout only (empty otherwise): its label PNG, which may not exist.
  std::vector<std::filesystem::path> label_files;
  // Per depth file, TUM only (empty otherwise): the capture time from the list.
  std::vector<std::int64_t> timestamps_ns;
  // Depth PNG units per metre by the layout's convention: 1000 (mm), TUM 5000.
  double depth_units_per_metre = 1000.0;
};

// True when `path` is a glob rather than a folder ('*' or '?' in it).
bool is_glob(const std::string& path);

// `path` is one of
// - a dataset folder DIR: frames are DIR/depth/*.png;
// - a flat folder DIR without depth/ that holds DIR/*-depth.png (labels DIR/*-label.png);
// - a TUM RGB-D folder DIR without depth/ that holds associations.txt or depth.txt (the former
//   preferred), or such a list file itself (any *.txt): lines "timestamp path" (depth.txt) or
//   "timestamp path timestamp path" (associate.py output; the pair whose path names depth is
//   taken), '#' starts a comment, paths relative to the list's folder;
// - a glob whose wildcards are in the file name only (e.g. DIR/depth/learn*.png, or
//   DIR/*-depth.png for the flat layout).
// Throws facet::StageError when the folder is missing or holds no frames, or (naming file and
// line) when a TUM list is malformed.
FrameListing list_frames(const std::string& path);

// Parses a TUM timestamp in seconds ("1305031102.175304") into nanoseconds without going
// through floating point. Returns false when `text` is not such a number.
bool parse_seconds(const std::string& text, std::int64_t& nanoseconds);

// Converts a CV_16UC1 depth image with `units_per_metre` units per metre into millimetres
// (rounded; values that would exceed 65535 mm become 0). Returns `depth` itself for 1000.
cv::Mat depth_to_millimetres(const cv::Mat& depth, double units_per_metre);

// Shell-style match of a file name: '*' matches any run of characters, '?' one character.
bool wildcard_match(std::string_view pattern, std::string_view name);

}  // namespace facet::io
