#include "io/png_files.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "io/png_codec.hpp"

namespace facet::io {
namespace {

std::string quoted(const std::filesystem::path& file) {
  return "'" + file.string() + "'";
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    throw StageError("cannot read " + quoted(file) + ": file not found");
  }
  // One read of the known size: a stream iterator would grow the buffer byte by byte, and this
  // runs for every frame.
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) throw StageError("cannot read " + quoted(file) + ": " + error.message());
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  std::ifstream in(file, std::ios::binary);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!in || in.gcount() != static_cast<std::streamsize>(bytes.size())) {
    throw StageError("cannot read " + quoted(file) + ": read error");
  }
  if (bytes.empty()) throw StageError("cannot read " + quoted(file) + ": the file is empty");
  return bytes;
}

// The dataset's own PNGs (grey 8/16-bit, RGB) go through the fast codec; anything else it does
// not handle (palette, alpha, interlaced PNGs, other formats) through OpenCV. IMREAD_UNCHANGED
// keeps 16 bits; the default flags would squash the image to 8-bit colour.
cv::Mat read_unchanged(const std::filesystem::path& file) {
  const std::vector<std::uint8_t> bytes = read_bytes(file);
  if (png::has_signature(bytes)) {
    try {
      if (std::optional<cv::Mat> image = png::decode(bytes)) return *std::move(image);
    } catch (const png::FormatError& e) {
      throw StageError("cannot read " + quoted(file) + ": " + e.what());
    }
  }
  cv::Mat image;
  try {
    image = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw StageError("cannot read " + quoted(file) + ": " + e.what());
  }
  if (image.empty()) {
    throw StageError("cannot read " + quoted(file) +
                     ": not a readable image (truncated, corrupt "
                     "or not a PNG)");
  }
  return image;
}

void check_size(const std::filesystem::path& file, const cv::Mat& image,
                const CameraIntrinsics& camera) {
  if (image.cols != camera.width || image.rows != camera.height) {
    throw StageError(quoted(file) + " is " + size_text(image.cols, image.rows) +
                     " but the intrinsics say " + size_text(camera.width, camera.height));
  }
}

}  // namespace

cv::Mat read_depth_png(const std::filesystem::path& file, const CameraIntrinsics& camera) {
  cv::Mat image = read_unchanged(file);
  if (image.channels() != 1) {
    throw StageError(quoted(file) + " has " + std::to_string(image.channels()) +
                     " channels; depth must be a single-channel 16-bit PNG in millimetres");
  }
  if (image.depth() != CV_16U) {
    const bool eight_bit = image.depth() == CV_8U;
    throw StageError(quoted(file) + (eight_bit ? " is 8-bit" : " is not 16-bit unsigned") +
                     "; depth must be a 16-bit PNG in millimetres (an 8-bit image cannot hold "
                     "depth; was it saved as a preview?)");
  }
  check_size(file, image, camera);
  return image;
}

cv::Mat read_label_png(const std::filesystem::path& file, const CameraIntrinsics& camera) {
  const cv::Mat image = read_unchanged(file);
  if (image.channels() != 1 || (image.depth() != CV_16U && image.depth() != CV_8U)) {
    throw StageError(quoted(file) + ": labels must be a single-channel 8- or 16-bit PNG");
  }
  check_size(file, image, camera);
  cv::Mat labels;
  image.convertTo(labels, CV_32S);
  return labels;
}

void write_png(const std::filesystem::path& file, const cv::Mat& image,
               const png::EncodeOptions& options) {
  CV_Assert(image.type() == CV_16UC1 || image.type() == CV_8UC1 || image.type() == CV_8UC3);
  const std::vector<std::uint8_t> bytes = png::encode(image, options);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw StageError("cannot write " + quoted(file) + ": " + std::strerror(errno));
}

}  // namespace facet::io
