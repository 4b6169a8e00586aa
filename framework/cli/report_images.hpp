#pragma once
// Images for the comparison report: what each variant's sinks wrote, found in the variants'
// output folders, made small and embedded as PNG data URIs (the report works offline).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace facet::cli {

// One frame of one output folder (e.g. "edges", frame "learn0"), one image per variant.
struct ImageRow {
  std::string folder;                  // relative to the variant's output folder
  std::string stem;                    // the frame's file stem
  std::vector<std::string> data_uris;  // per variant, in order; empty where it wrote none
  std::string input_uri;               // the frame's input depth, when found
  std::string truth_uri;               // its ground truth, when found
};

// The frames of every folder with PNGs below the variants' output folders whose stems are in
// `stems`, in that order, each image at most `max_width` pixels wide.
std::vector<ImageRow> collect_variant_images(
    const std::vector<std::pair<std::string, std::filesystem::path>>& variant_dirs,
    const std::vector<std::string>& stems, int max_width);

// A PNG file as "data:image/png;base64,..." for display: label images (16- or 32-bit ids) get
// one colour per id (0 black), anything wider than max_width is shrunk. Empty if unreadable.
std::string png_data_uri(const std::filesystem::path& file, int max_width);

// A 16-bit depth PNG (mm) as a grey picture, near bright and far dark, no depth black.
std::string depth_data_uri(const std::filesystem::path& file, int max_width);

}  // namespace facet::cli
