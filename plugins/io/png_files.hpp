#pragma once
// Reading and writing the 16-bit PNGs of the dataset format (see docs/data-formats.md).
// Every function throws facet::StageError naming the file and what is wrong with it.

#include <filesystem>
#include <opencv2/core/mat.hpp>

#include "facet/types/frame.hpp"
#include "io/png_codec.hpp"

namespace facet::io {

// A depth PNG: single-channel 16-bit, millimetres, 0 = invalid, of the camera's size.
// Returns CV_16UC1.
cv::Mat read_depth_png(const std::filesystem::path& file, const CameraIntrinsics& camera);

// A label PNG: single-channel 8- or 16-bit, 0 = background, of the camera's size.
// Returns CV_32SC1.
cv::Mat read_label_png(const std::filesystem::path& file, const CameraIntrinsics& camera);

// Writes a CV_16UC1 (16-bit), CV_8UC1 (8-bit grey) or CV_8UC3 (BGR colour) image as a PNG.
// Label images are written faster with {.deflate = png::Deflate::runs}.
void write_png(const std::filesystem::path& file, const cv::Mat& image,
               const png::EncodeOptions& options = {});

}  // namespace facet::io
