#include "io/png_files.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "io/output_folder.hpp"
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

void check_size(const std::filesystem::path& file, int width, int height,
                const CameraIntrinsics& camera) {
  if (width != camera.width || height != camera.height) {
    throw StageError(quoted(file) + " is " + size_text(width, height) + " but the intrinsics say " +
                     size_text(camera.width, camera.height));
  }
}

// The dataset's own PNGs (grey 8/16-bit, RGB) go through the fast codec; the PNGs it does not
// handle (palette, alpha, interlaced) through OpenCV. IMREAD_UNCHANGED keeps 16 bits; the default
// flags would squash the image to 8-bit colour.
// A PNG's size is checked against the camera's before a pixel is allocated (a 69-byte file may
// declare 23170x23170 pixels), and a PNG left to OpenCV is checked for integrity first: libpng
// only warns about corrupt image data and decodes garbage.
// Bytes without a PNG signature are refused, not handed to OpenCV's other decoders: those
// allocate what their header declares before this check could run (a 97-byte JPEG 2000
// codestream asks for 1.8 GB), and no depth or label format we read is anything but PNG.
cv::Mat read_unchanged(const std::filesystem::path& file, const CameraIntrinsics& camera) {
  const std::vector<std::uint8_t> bytes = read_bytes(file);
  if (!png::has_signature(bytes)) {
    throw StageError("cannot read " + quoted(file) +
                     ": not a PNG file (no PNG signature); depth and labels are read from PNGs");
  }
  try {
    const png::Info info = png::read_info(bytes);
    if (info.width > static_cast<std::uint32_t>(std::numeric_limits<int>::max()) ||
        info.height > static_cast<std::uint32_t>(std::numeric_limits<int>::max())) {
      throw png::FormatError("its header declares " + std::to_string(info.width) + "x" +
                             std::to_string(info.height) + " pixels");
    }
    check_size(file, static_cast<int>(info.width), static_cast<int>(info.height), camera);
    if (std::optional<cv::Mat> image = png::decode(bytes)) return *std::move(image);
    png::check_integrity(bytes);
  } catch (const png::FormatError& e) {
    throw StageError("cannot read " + quoted(file) + ": " + e.what());
  }
  cv::Mat image;
  try {
    image = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw StageError("cannot read " + quoted(file) + ": " + e.what());
  }
  if (image.empty()) {
    throw StageError("cannot read " + quoted(file) + ": not a readable PNG (truncated or corrupt)");
  }
  check_size(file, image.cols, image.rows, camera);
  return image;
}

}  // namespace

cv::Mat read_depth_png(const std::filesystem::path& file, const CameraIntrinsics& camera) {
  cv::Mat image = read_unchanged(file, camera);
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
  return image;
}

cv::Mat read_label_png(const std::filesystem::path& file, const CameraIntrinsics& camera) {
  const cv::Mat image = read_unchanged(file, camera);
  if (image.channels() != 1 || (image.depth() != CV_16U && image.depth() != CV_8U)) {
    throw StageError(quoted(file) + ": labels must be a single-channel 8- or 16-bit PNG");
  }
  cv::Mat labels;
  image.convertTo(labels, CV_32S);
  return labels;
}

void write_png(const std::filesystem::path& file, const cv::Mat& image,
               const png::EncodeOptions& options) {
  CV_Assert(image.type() == CV_16UC1 || image.type() == CV_8UC1 || image.type() == CV_8UC3);
  const std::vector<std::uint8_t> bytes = png::encode(image, options);
  write_file_atomically(
      file, {std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())});
}

}  // namespace facet::io
