#pragma once
// Writing the images of the dataset format (docs/data-formats.md): depth as 16-bit millimetres
// and labels as 16-bit ids, shared by io.depth, io.labels and io.record. Every function throws
// facet::StageError naming the file when the image cannot be written in the format.

#include <cstdint>
#include <filesystem>
#include <opencv2/core/mat.hpp>

#include "facet/context.hpp"

namespace facet::io {

// Depth CV_16UC1 (mm, written as is) or CV_32FC1 (m: rounded to mm; NaN, 0, negative and
// infinite become 0, as do valid depths beyond 65.535 m). Returns how many valid depths were
// beyond 65.535 m.
std::int64_t write_depth_png(const std::filesystem::path& file, const cv::Mat& depth);

// The same, for a sink: warns through `ctx`, naming the file, when depths beyond 65.535 m were
// written as 0.
void write_depth_png(ProcessContext& ctx, const std::filesystem::path& file, const cv::Mat& depth);

// Labels CV_32SC1, CV_16UC1 or CV_8UC1, ids 0..65535 (0 = background).
void write_label_png(const std::filesystem::path& file, const cv::Mat& labels);

}  // namespace facet::io
