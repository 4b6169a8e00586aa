#pragma once
// Reading camera intrinsics from a dataset's intrinsics.yaml.

#include <filesystem>

#include "facet/types/frame.hpp"

namespace facet::io {

// Reads the keys fx, fy, cx, cy (pixels) and width, height (pixels) of a plain YAML file.
// Throws facet::StageError naming the file (and line and key, where there is one) when the file
// is missing, is not YAML, lacks a key, or holds a value that is not a usable number.
CameraIntrinsics read_intrinsics(const std::filesystem::path& file);

// Writes the keys read_intrinsics reads, at full precision (a written file reads back exactly).
// Throws facet::StageError naming the file when it cannot be written.
void write_intrinsics(const std::filesystem::path& file, const CameraIntrinsics& camera);

}  // namespace facet::io
