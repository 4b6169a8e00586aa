#include "io/png_codec.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>

#include "io/run_deflate.hpp"

namespace facet::io::png {
namespace {

constexpr std::array<std::uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// Larger images are left to the general decoder (which will likely refuse them too): the limit
// keeps the size arithmetic far from overflow and a corrupt header from allocating gigabytes.
constexpr std::uint64_t kMaxImageBytes = std::uint64_t{1} << 30;

// PNG's colour types (specification section 11.2.2) that this codec handles.
constexpr std::uint8_t kGrey = 0;
constexpr std::uint8_t kRgb = 2;

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};
struct DecompressorDeleter {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

std::uint32_t read_u32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  out.push_back(static_cast<std::uint8_t>(value >> 24));
  out.push_back(static_cast<std::uint8_t>(value >> 16));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
  out.push_back(static_cast<std::uint8_t>(value));
}

// A chunk is its length, type, data and a CRC over type and data. The header is appended first,
// the data by the caller, then the CRC over everything from the type on.
void append_chunk_header(std::vector<std::uint8_t>& out, std::string_view type,
                         std::size_t length) {
  append_u32(out, static_cast<std::uint32_t>(length));
  for (const char c : type)
    out.push_back(static_cast<std::uint8_t>(c));
}
void append_crc(std::vector<std::uint8_t>& out, std::size_t chunk_type_offset) {
  const std::size_t length = out.size() - chunk_type_offset;
  append_u32(out, libdeflate_crc32(0, out.data() + chunk_type_offset, length));
}

// PNG's Paeth predictor: of left, up and up-left, the one closest to left + up - up_left (ties
// in that order). Written with selects instead of branches: on depth images the choice is
// close to random, and mispredicted branches made this the decoder's hottest loop.
std::uint8_t paeth_predictor(int left, int up, int up_left) {
  const int to_left = std::abs(up - up_left);  // |estimate - left|
  const int to_up = std::abs(left - up_left);
  const int to_up_left = std::abs(left + up - 2 * up_left);
  const int left_or_up = to_up < to_left ? up : left;
  const int closest = std::min(to_left, to_up);
  return static_cast<std::uint8_t>(to_up_left < closest ? up_left : left_or_up);
}

// One row of `image` as PNG stores it: samples big-endian, colour as RGB.
void pack_row(const cv::Mat& image, int row, std::uint8_t* out) {
  const int width = image.cols;
  switch (image.type()) {
    case CV_8UC1:
      std::memcpy(out, image.ptr<std::uint8_t>(row), static_cast<std::size_t>(width));
      break;
    case CV_16UC1: {
      const auto* in = image.ptr<std::uint16_t>(row);
      for (int x = 0; x < width; ++x) {
        out[2 * x] = static_cast<std::uint8_t>(in[x] >> 8);
        out[2 * x + 1] = static_cast<std::uint8_t>(in[x]);
      }
      break;
    }
    default: {  // CV_8UC3, BGR
      const auto* in = image.ptr<std::uint8_t>(row);
      for (int x = 0; x < width; ++x) {
        out[3 * x] = in[3 * x + 2];
        out[3 * x + 1] = in[3 * x + 1];
        out[3 * x + 2] = in[3 * x];
      }
      break;
    }
  }
}

// Writes the filter byte and the filtered row. `previous` is the packed row above (zeros for the
// first row). One loop per filter, so that none of them branches per byte.
void filter_row(Filter filter, const std::uint8_t* row, const std::uint8_t* previous,
                std::size_t row_bytes, std::size_t pixel_bytes, std::uint8_t* out) {
  out[0] = static_cast<std::uint8_t>(filter);
  std::uint8_t* filtered = out + 1;
  const std::size_t first = std::min(pixel_bytes, row_bytes);  // bytes with no left neighbour
  switch (filter) {
    case Filter::none:
      std::memcpy(filtered, row, row_bytes);
      return;
    case Filter::sub:
      std::memcpy(filtered, row, first);
      for (std::size_t i = first; i < row_bytes; ++i)
        filtered[i] = static_cast<std::uint8_t>(row[i] - row[i - pixel_bytes]);
      return;
    case Filter::up:
      for (std::size_t i = 0; i < row_bytes; ++i)
        filtered[i] = static_cast<std::uint8_t>(row[i] - previous[i]);
      return;
    case Filter::average:
      for (std::size_t i = 0; i < first; ++i)
        filtered[i] = static_cast<std::uint8_t>(row[i] - previous[i] / 2);
      for (std::size_t i = first; i < row_bytes; ++i)
        filtered[i] = static_cast<std::uint8_t>(row[i] - (row[i - pixel_bytes] + previous[i]) / 2);
      return;
    case Filter::paeth:
      for (std::size_t i = 0; i < first; ++i)
        filtered[i] = static_cast<std::uint8_t>(row[i] - previous[i]);
      for (std::size_t i = first; i < row_bytes; ++i) {
        filtered[i] = static_cast<std::uint8_t>(
            row[i] - paeth_predictor(row[i - pixel_bytes], previous[i], previous[i - pixel_bytes]));
      }
      return;
  }
}

// Undoes the filter of one row in place, for pixels of kPixelBytes bytes. `previous` is the row
// above, already unfiltered, or nullptr for the first row (which the specification treats as a
// row of zeros). Every byte depends on the one a pixel to its left; that neighbour is carried in
// `left` rather than read back from the row, which would wait on the store just made.
template <std::size_t kPixelBytes>
void unfilter_row(std::uint8_t filter, std::uint8_t* row, const std::uint8_t* previous,
                  std::size_t row_bytes) {
  static const std::uint8_t kZeros[kPixelBytes] = {};
  if (filter > 4) {
    throw FormatError("row filter " + std::to_string(filter) + " is not one of PNG's 0-4");
  }
  if (filter == 0 || (filter == 2 && previous == nullptr)) return;
  if (filter == 2) {
    for (std::size_t i = 0; i < row_bytes; ++i)
      row[i] = static_cast<std::uint8_t>(row[i] + previous[i]);
    return;
  }
  std::uint8_t left[kPixelBytes] = {};
  if (filter == 1 || (filter == 4 && previous == nullptr)) {  // Paeth predicts from the left here
    for (std::size_t i = 0; i + kPixelBytes <= row_bytes; i += kPixelBytes) {
      for (std::size_t k = 0; k < kPixelBytes; ++k)
        row[i + k] = left[k] = static_cast<std::uint8_t>(row[i + k] + left[k]);
    }
    return;
  }
  const std::uint8_t* up_row = previous != nullptr ? previous : kZeros;
  const std::size_t up_step = previous != nullptr ? kPixelBytes : 0;
  if (filter == 3) {
    for (std::size_t i = 0, j = 0; i + kPixelBytes <= row_bytes; i += kPixelBytes, j += up_step) {
      for (std::size_t k = 0; k < kPixelBytes; ++k) {
        row[i + k] = left[k] =
            static_cast<std::uint8_t>(row[i + k] + ((left[k] + up_row[j + k]) >> 1));
      }
    }
    return;
  }
  std::uint8_t up_left[kPixelBytes] = {};
  for (std::size_t i = 0; i + kPixelBytes <= row_bytes; i += kPixelBytes) {
    for (std::size_t k = 0; k < kPixelBytes; ++k) {
      const std::uint8_t up = previous[i + k];
      row[i + k] = left[k] =
          static_cast<std::uint8_t>(row[i + k] + paeth_predictor(left[k], up, up_left[k]));
      up_left[k] = up;
    }
  }
}

void unfilter_row(std::uint8_t filter, std::uint8_t* row, const std::uint8_t* previous,
                  std::size_t row_bytes, std::size_t pixel_bytes) {
  switch (pixel_bytes) {
    case 1:
      return unfilter_row<1>(filter, row, previous, row_bytes);
    case 2:
      return unfilter_row<2>(filter, row, previous, row_bytes);
    case 3:
      return unfilter_row<3>(filter, row, previous, row_bytes);
    default:
      throw FormatError(std::to_string(pixel_bytes) + " bytes a pixel is not a handled format");
  }
}

struct Header {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint8_t bit_depth = 0;
  std::uint8_t colour_type = 0;
  std::uint8_t interlace = 0;
};

Header parse_header(const std::uint8_t* data, std::uint32_t length) {
  if (length != 13)
    throw FormatError("IHDR chunk has " + std::to_string(length) + " bytes, not 13");
  Header header;
  header.width = read_u32(data);
  header.height = read_u32(data + 4);
  header.bit_depth = data[8];
  header.colour_type = data[9];
  header.interlace = data[12];
  if (header.width == 0 || header.height == 0)
    throw FormatError("image has a zero width or height");
  if (data[10] != 0 || data[11] != 0) throw FormatError("unknown compression or filter method");
  return header;
}

bool handled(const Header& header) {
  const bool grey =
      header.colour_type == kGrey && (header.bit_depth == 8 || header.bit_depth == 16);
  const bool rgb = header.colour_type == kRgb && header.bit_depth == 8;
  return (grey || rgb) && header.interlace == 0;
}

// Copies the unfiltered rows into an OpenCV image: samples to host order, RGB to BGR.
cv::Mat unpack(const Header& header, const std::uint8_t* rows, std::size_t stride) {
  const int width = static_cast<int>(header.width);
  const int height = static_cast<int>(header.height);
  if (header.colour_type == kRgb) {
    cv::Mat image(height, width, CV_8UC3);
    for (int y = 0; y < height; ++y) {
      const std::uint8_t* in = rows + static_cast<std::size_t>(y) * stride;
      auto* out = image.ptr<std::uint8_t>(y);
      for (int x = 0; x < width; ++x) {
        out[3 * x] = in[3 * x + 2];
        out[3 * x + 1] = in[3 * x + 1];
        out[3 * x + 2] = in[3 * x];
      }
    }
    return image;
  }
  if (header.bit_depth == 8) {
    cv::Mat image(height, width, CV_8UC1);
    for (int y = 0; y < height; ++y)
      std::memcpy(image.ptr(y), rows + static_cast<std::size_t>(y) * stride,
                  static_cast<std::size_t>(width));
    return image;
  }
  cv::Mat image(height, width, CV_16UC1);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* in = rows + static_cast<std::size_t>(y) * stride;
    auto* out = image.ptr<std::uint16_t>(y);
    for (int x = 0; x < width; ++x)
      out[x] = static_cast<std::uint16_t>((in[2 * x] << 8) | in[2 * x + 1]);
  }
  return image;
}

std::vector<std::uint8_t> zlib_compress(std::span<const std::uint8_t> data, int level) {
  const std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(
      libdeflate_alloc_compressor(std::clamp(level, 1, 12)));
  if (!compressor) throw std::bad_alloc();
  std::vector<std::uint8_t> out(libdeflate_zlib_compress_bound(compressor.get(), data.size()));
  const std::size_t size =
      libdeflate_zlib_compress(compressor.get(), data.data(), data.size(), out.data(), out.size());
  if (size == 0) throw std::runtime_error("png::encode: deflate output exceeded its bound");
  out.resize(size);
  return out;
}

}  // namespace

std::vector<std::uint8_t> encode(const cv::Mat& image, const EncodeOptions& options) {
  const int type = image.type();
  if (image.empty() || (type != CV_8UC1 && type != CV_16UC1 && type != CV_8UC3)) {
    throw std::invalid_argument("png::encode takes a non-empty CV_8UC1, CV_16UC1 or CV_8UC3 image");
  }
  const std::size_t pixel_bytes = image.elemSize();
  const std::size_t row_bytes = pixel_bytes * static_cast<std::size_t>(image.cols);
  const std::size_t stride = row_bytes + 1;

  // Filter every row into one buffer, the uncompressed zlib payload.
  std::vector<std::uint8_t> filtered(stride * static_cast<std::size_t>(image.rows));
  std::vector<std::uint8_t> rows(2 * row_bytes, 0);  // this row and the one above, packed
  std::uint8_t* current = rows.data();
  std::uint8_t* previous = rows.data() + row_bytes;
  for (int y = 0; y < image.rows; ++y) {
    pack_row(image, y, current);
    filter_row(options.filter, current, previous, row_bytes, pixel_bytes,
               filtered.data() + static_cast<std::size_t>(y) * stride);
    std::swap(current, previous);
  }

  const std::vector<std::uint8_t> zlib = options.deflate == Deflate::runs
                                             ? zlib_compress_runs(filtered)
                                             : zlib_compress(filtered, options.level);

  std::vector<std::uint8_t> out;
  out.reserve(kSignature.size() + 25 + 12 + zlib.size() + 12);
  for (const std::uint8_t byte : kSignature)
    out.push_back(byte);

  append_chunk_header(out, "IHDR", 13);
  const std::size_t ihdr_type = out.size() - 4;
  append_u32(out, static_cast<std::uint32_t>(image.cols));
  append_u32(out, static_cast<std::uint32_t>(image.rows));
  out.push_back(static_cast<std::uint8_t>(image.depth() == CV_16U ? 16 : 8));
  out.push_back(image.channels() == 3 ? kRgb : kGrey);
  out.push_back(0);  // compression: deflate
  out.push_back(0);  // filter method: adaptive (per-row filter bytes)
  out.push_back(0);  // no interlace
  append_crc(out, ihdr_type);

  append_chunk_header(out, "IDAT", zlib.size());
  const std::size_t idat_type = out.size() - 4;
  out.resize(out.size() + zlib.size());
  std::memcpy(out.data() + idat_type + 4, zlib.data(), zlib.size());
  append_crc(out, idat_type);

  append_chunk_header(out, "IEND", 0);
  append_crc(out, out.size() - 4);
  return out;
}

bool has_signature(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= kSignature.size() &&
         std::equal(kSignature.begin(), kSignature.end(), bytes.begin());
}

namespace {

// What a walk over all chunks finds: the header, the image data and whether every critical
// chunk is one this codec knows.
struct Chunks {
  Header header;
  std::vector<std::uint8_t> compressed;
  bool only_known_critical = true;
};

// Checks the signature, every chunk's length and CRC and the chunk order (IHDR first, IEND
// last); throws FormatError where they are wrong.
Chunks read_chunks(std::span<const std::uint8_t> bytes) {
  if (!has_signature(bytes)) throw FormatError("not a PNG file (no PNG signature)");
  Chunks chunks;
  bool have_header = false;
  bool ended = false;
  std::size_t at = kSignature.size();
  while (!ended) {
    if (bytes.size() - at < 12) throw FormatError("file is truncated (a chunk is cut off)");
    const std::uint32_t length = read_u32(bytes.data() + at);
    const std::uint8_t* type = bytes.data() + at + 4;
    const std::string_view type_name(reinterpret_cast<const char*>(type), 4);
    if (length > bytes.size() - at - 12) {
      throw FormatError("file is truncated (chunk " + std::string(type_name) + " is cut off)");
    }
    const std::uint8_t* data = type + 4;
    const std::uint32_t stored_crc = read_u32(data + length);
    if (libdeflate_crc32(0, type, length + 4u) != stored_crc) {
      throw FormatError("chunk " + std::string(type_name) + " fails its CRC check (corrupt file)");
    }
    at += 12 + std::size_t{length};

    if (!have_header) {
      if (type_name != "IHDR")
        throw FormatError("first chunk is " + std::string(type_name) + ", not IHDR");
      chunks.header = parse_header(data, length);
      have_header = true;
    } else if (type_name == "IDAT") {
      chunks.compressed.insert(chunks.compressed.end(), data, data + length);
    } else if (type_name == "IEND") {
      ended = true;
    } else if ((type[0] & 0x20) == 0 && type_name != "PLTE") {
      chunks.only_known_critical = false;  // a critical chunk this codec does not know
    }
  }
  if (chunks.compressed.empty()) throw FormatError("no image data (IDAT chunk)");
  return chunks;
}

// Samples per pixel of a colour type, for the bit depths the specification allows it
// (section 11.2.2); FormatError for any other combination.
std::uint64_t bits_per_pixel(const Header& header) {
  const auto depth_in = [&](std::initializer_list<int> depths) {
    for (const int depth : depths) {
      if (header.bit_depth == depth) return true;
    }
    return false;
  };
  std::uint64_t samples = 0;
  bool allowed = false;
  switch (header.colour_type) {
    case 0:  // grey
      samples = 1;
      allowed = depth_in({1, 2, 4, 8, 16});
      break;
    case 2:  // RGB
      samples = 3;
      allowed = depth_in({8, 16});
      break;
    case 3:  // palette
      samples = 1;
      allowed = depth_in({1, 2, 4, 8});
      break;
    case 4:  // grey and alpha
      samples = 2;
      allowed = depth_in({8, 16});
      break;
    case 6:  // RGBA
      samples = 4;
      allowed = depth_in({8, 16});
      break;
    default:
      break;
  }
  if (!allowed) {
    throw FormatError("colour type " + std::to_string(header.colour_type) + " at bit depth " +
                      std::to_string(header.bit_depth) + " is not a PNG format");
  }
  return samples * header.bit_depth;
}

// The bytes the image data inflates to: filtered rows of each Adam7 pass when interlaced
// (specification section 8.2), of the whole image otherwise, a filter byte per row.
std::uint64_t raw_data_bytes(const Header& header) {
  const std::uint64_t bits = bits_per_pixel(header);
  const auto rows_bytes = [&](std::uint64_t width, std::uint64_t height) -> std::uint64_t {
    if (width == 0 || height == 0) return 0;
    return ((width * bits + 7) / 8 + 1) * height;
  };
  if (header.interlace == 0) return rows_bytes(header.width, header.height);
  if (header.interlace != 1) throw FormatError("unknown interlace method");
  struct Pass {
    std::uint64_t x0, y0, dx, dy;
  };
  constexpr Pass kAdam7[] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                             {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};
  std::uint64_t total = 0;
  for (const Pass& pass : kAdam7) {
    const auto count = [](std::uint64_t size, std::uint64_t start, std::uint64_t step) {
      return size > start ? (size - start + step - 1) / step : 0;
    };
    total +=
        rows_bytes(count(header.width, pass.x0, pass.dx), count(header.height, pass.y0, pass.dy));
  }
  return total;
}

// Inflates the image data into exactly `size` bytes, its Adler-32 checked; FormatError when the
// stream is corrupt or inflates to more or fewer bytes than the header declares.
std::vector<std::uint8_t> inflate_exactly(const Chunks& chunks, std::uint64_t size) {
  const Header& header = chunks.header;
  const std::string declared =
      std::to_string(header.width) + "x" + std::to_string(header.height) + " pixels";
  if (size > kMaxImageBytes) {
    throw FormatError("its header declares " + declared + ", larger than facet reads (" +
                      std::to_string(kMaxImageBytes >> 20) + " MiB of image data)");
  }
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(size));
  const std::unique_ptr<libdeflate_decompressor, DecompressorDeleter> decompressor(
      libdeflate_alloc_decompressor());
  if (!decompressor) throw std::bad_alloc();
  std::size_t produced = 0;
  const libdeflate_result result =
      libdeflate_zlib_decompress(decompressor.get(), chunks.compressed.data(),
                                 chunks.compressed.size(), rows.data(), rows.size(), &produced);
  if (result == LIBDEFLATE_INSUFFICIENT_SPACE) {
    throw FormatError("image data is longer than the header's " + declared + " (corrupt file)");
  }
  if (result != LIBDEFLATE_SUCCESS) throw FormatError("image data is corrupt (bad deflate stream)");
  if (produced != rows.size()) {
    throw FormatError("image data is shorter than the header's " + declared + " (truncated file?)");
  }
  return rows;
}

}  // namespace

Info read_info(std::span<const std::uint8_t> bytes) {
  if (!has_signature(bytes)) throw FormatError("not a PNG file (no PNG signature)");
  const std::size_t at = kSignature.size();
  if (bytes.size() < at + 8 + 13 + 4) throw FormatError("file is truncated (no IHDR chunk)");
  const std::uint8_t* type = bytes.data() + at + 4;
  if (std::string_view(reinterpret_cast<const char*>(type), 4) != "IHDR") {
    throw FormatError("first chunk is not IHDR");
  }
  const std::uint32_t length = read_u32(bytes.data() + at);
  if (length == 13 && libdeflate_crc32(0, type, 17) != read_u32(type + 17)) {
    throw FormatError("chunk IHDR fails its CRC check (corrupt file)");
  }
  const Header header = parse_header(type + 4, length);
  return {header.width, header.height, header.bit_depth, header.colour_type, header.interlace != 0};
}

void check_integrity(std::span<const std::uint8_t> bytes) {
  const Chunks chunks = read_chunks(bytes);
  (void)inflate_exactly(chunks, raw_data_bytes(chunks.header));
}

std::optional<cv::Mat> decode(std::span<const std::uint8_t> bytes) {
  const Chunks chunks = read_chunks(bytes);
  const Header& header = chunks.header;
  if (!handled(header) || !chunks.only_known_critical) return std::nullopt;

  const std::uint64_t pixel_bytes = (header.colour_type == kRgb ? 3u : 1u) * header.bit_depth / 8u;
  const std::uint64_t row_bytes = pixel_bytes * header.width;
  std::vector<std::uint8_t> rows = inflate_exactly(chunks, (row_bytes + 1) * header.height);

  const std::size_t stride = static_cast<std::size_t>(row_bytes) + 1;
  for (std::uint32_t y = 0; y < header.height; ++y) {
    std::uint8_t* row = rows.data() + std::size_t{y} * stride;
    const std::uint8_t* previous = y == 0 ? nullptr : row - stride + 1;
    unfilter_row(row[0], row + 1, previous, static_cast<std::size_t>(row_bytes),
                 static_cast<std::size_t>(pixel_bytes));
  }
  return unpack(header, rows.data() + 1, stride);
}

}  // namespace facet::io::png
