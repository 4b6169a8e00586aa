#pragma once
// A PNG encoder and decoder for the images facet reads and writes every frame: 8- and 16-bit
// grey (depth, labels, edges) and 8-bit colour (overlays), not interlaced.
//
// It exists for speed. OpenCV's PNG path (libpng on zlib, libpng choosing a filter per row by
// trying all five) took 3.4 ms to write one 640x480 overlay and 2 ms to read one depth frame,
// a third of the tabletop graph's time per frame. Here deflate is libdeflate's, several times
// faster than zlib's at the same ratio, and every row uses one fixed filter. Any other kind of
// PNG (palette, alpha, 1-4 bit, interlaced) is left to a general decoder: decode() says so by
// returning no image.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

namespace facet::io::png {

// A file that claims to be a PNG but is not a well-formed one (bad signature, truncated chunk,
// CRC mismatch, corrupt deflate stream, image data of the wrong size).
class FormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The row filters of the PNG specification (section 9.2).
enum class Filter : std::uint8_t { none = 0, sub = 1, up = 2, average = 3, paeth = 4 };

// How the filtered rows are deflated.
enum class Deflate : std::uint8_t {
  general,  // libdeflate: any image
  runs,     // only runs of one byte (run_deflate.hpp): label and mask images, several times faster
};

struct EncodeOptions {
  // Sub suits what facet writes: label and edge images are runs of equal values, depth and
  // overlays change smoothly along a row. Measured on the mOSD frames in docs/performance.md.
  Filter filter = Filter::sub;
  // libdeflate's compression level, 1 to 12. Not 1: libdeflate 1.14's level 1 is 2x slower than
  // level 2 on long runs of one value (label images, overlay backgrounds), at the same size.
  int level = 2;
  Deflate deflate = Deflate::general;
};

// Encodes a CV_8UC1, CV_16UC1 or CV_8UC3 (BGR, stored as RGB as PNG wants) image.
// Throws std::invalid_argument for any other type or an empty image.
std::vector<std::uint8_t> encode(const cv::Mat& image, const EncodeOptions& options = {});

// Whether `bytes` start with the PNG signature.
bool has_signature(std::span<const std::uint8_t> bytes);

// What a PNG's header declares, read without decoding anything (to refuse an image of the wrong
// size before its pixels are allocated).
struct Info {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint8_t bit_depth = 0;
  std::uint8_t colour_type = 0;
  bool interlaced = false;
};

// Throws FormatError for bytes that do not start with the signature and a well-formed IHDR.
Info read_info(std::span<const std::uint8_t> bytes);

// Decodes a non-interlaced 8- or 16-bit grey or 8-bit RGB PNG into CV_8UC1, CV_16UC1 or CV_8UC3
// (BGR). Returns std::nullopt for any other well-formed PNG. Throws FormatError for bytes that
// are not a well-formed PNG: a bad signature, chunk length or CRC, image data that is corrupt
// (Adler-32 included) or inflates to more or fewer bytes than the header declares, or image data
// above 1 GiB.
std::optional<cv::Mat> decode(std::span<const std::uint8_t> bytes);

// For the PNGs decode() leaves to a general decoder (palette, alpha, 1-4 bit, interlaced): the
// same checks of every chunk and of the image data, which is inflated to the size the header
// declares and then dropped. libpng, seeing a bad data check, only warns and decodes garbage.
// Throws FormatError.
void check_integrity(std::span<const std::uint8_t> bytes);

}  // namespace facet::io::png
