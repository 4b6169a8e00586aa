#pragma once
// Reading camera intrinsics from a dataset's intrinsics.yaml.

#include <filesystem>

#include "facet/types/frame.hpp"

namespace facet::io {

// The plausible ranges read_intrinsics accepts: focal lengths from 1 to 100 000 px (a 640 px
// wide image at 0.4 degrees of field of view), sizes up to 32768 px, the principal point within
// the image widened by its size on each side.
inline constexpr double kMinFocalLengthPx = 1.0;
inline constexpr double kMaxFocalLengthPx = 1.0e5;
inline constexpr int kMaxIntrinsicsSizePx = 32768;

// Reads the keys fx, fy, cx, cy (pixels) and width, height (pixels) of a plain YAML file.
// Throws facet::StageError naming the file (and line and key, where there is one) when the file
// is missing, is not YAML, lacks a key, says a key twice, or holds a value that is not a usable
// number or lies outside the ranges above (NaN and infinities among them).
CameraIntrinsics read_intrinsics(const std::filesystem::path& file);

// Writes the keys read_intrinsics reads, at full precision (a written file reads back exactly).
// Throws facet::StageError naming the file when it cannot be written.
void write_intrinsics(const std::filesystem::path& file, const CameraIntrinsics& camera);

}  // namespace facet::io
