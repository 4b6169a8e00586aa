#pragma once
// Writes depth frames as an .oni recording that OpenNI2's file driver (OniFile) plays back: one
// depth stream of uncompressed 1 mm pixels, in OpenNI2's file format version 1.0.1.0 (64-bit
// positions). This is the subset of the format a player needs (docs/cameras.md lists the
// records); no colour, no seek table, no compression. It lets the project make recordings
// without a camera: for tests of io.openni2's playback, and to turn any depth stream into a file
// every OpenNI2 tool opens.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <opencv2/core/mat.hpp>

namespace facet::openni2 {

struct OniStreamInfo {
  int width_px = 0;
  int height_px = 0;
  int fps = 30;
  double hfov_rad = 0.0;  // field of view the player reports (getHorizontalFieldOfView)
  double vfov_rad = 0.0;
};

class OniDepthWriter {
 public:
  // Creates `file` and writes the stream's description. Throws facet::StageError naming the file
  // when it cannot be written or `info` is not a usable depth stream.
  OniDepthWriter(std::filesystem::path file, const OniStreamInfo& info);
  ~OniDepthWriter();  // finishes the file if finish() was not called (errors are then lost)
  OniDepthWriter(const OniDepthWriter&) = delete;
  OniDepthWriter& operator=(const OniDepthWriter&) = delete;

  // Appends one frame: CV_16UC1 mm of the stream's size, stamped `timestamp_us` (microseconds,
  // not decreasing). Throws facet::StageError naming the file on a wrong image or a write error.
  void add(const cv::Mat& depth_mm, std::uint64_t timestamp_us);

  // Writes the end record and the frame count and time range into the description; the file is
  // complete. Throws facet::StageError naming the file on a write error.
  void finish();

  std::uint32_t frames() const { return frames_; }

 private:
  void fail(const std::string& what) const;

  std::filesystem::path file_;
  OniStreamInfo info_;
  std::ofstream out_;
  std::streamoff global_max_pos_ = 0;  // where the counts and times are patched in by finish()
  std::streamoff node_frames_pos_ = 0;
  std::streamoff data_begin_pos_ = 0;
  std::uint32_t frames_ = 0;
  std::uint64_t first_us_ = 0;
  std::uint64_t last_us_ = 0;
  bool finished_ = false;
};

}  // namespace facet::openni2
