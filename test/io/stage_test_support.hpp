#pragma once
// Helpers shared by the stage tests: temporary folders, tiny datasets, error checks.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <string_view>

#include "facet/error.hpp"
#include "temp_dir.hpp"

namespace facet::test {

inline std::filesystem::path data_dir() {
  return std::filesystem::path(FACET_TEST_DATA_DIR);
}

inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

inline void write_png(const std::filesystem::path& file, const cv::Mat& image) {
  std::filesystem::create_directories(file.parent_path());
  ASSERT_TRUE(cv::imwrite(file.string(), image)) << file;
}

inline std::string intrinsics_yaml(int width, int height) {
  return "# test camera\nfx: 500.0\nfy: 500.0\ncx: " + std::to_string(width / 2) +
         "\ncy: " + std::to_string(height / 2) + "\nwidth: " + std::to_string(width) +
         "\nheight: " + std::to_string(height) + "\n";
}

// A depth image whose every pixel encodes the frame number, so tests can tell frames apart.
inline cv::Mat depth_mm(int width, int height, std::uint16_t value) {
  return cv::Mat(height, width, CV_16UC1, cv::Scalar(value));
}

// Runs `action` and checks that it throws facet::StageError whose message contains every part.
inline void expect_stage_error(const std::function<void()>& action,
                               std::initializer_list<std::string_view> parts) {
  try {
    action();
    ADD_FAILURE() << "expected facet::StageError";
  } catch (const StageError& error) {
    const std::string message = error.what();
    for (const std::string_view part : parts) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "message \"" << message << "\" does not contain \"" << part << "\"";
    }
  }
}

}  // namespace facet::test
