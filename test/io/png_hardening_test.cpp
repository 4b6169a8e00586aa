// Depth and label PNGs from strangers: a size is refused before its pixels are allocated, and
// image data that is corrupt, or longer than its header says, is an error naming the file, also
// for the PNGs left to OpenCV (libpng only warns about them and decodes garbage); other formats
// are refused before any decoder allocates what their header declares.
#include <gtest/gtest.h>

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "io/png_codec.hpp"
#include "io/png_files.hpp"
#include "stage_test_support.hpp"

namespace {

namespace png = facet::io::png;
using Bytes = std::vector<std::uint8_t>;
using facet::test::expect_stage_error;
using facet::test::TempDir;

// Written out here rather than taken from the codec under test.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
  std::uint32_t crc = 0xffffffffU;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc >> 1) ^ (0xedb88320U & (0U - (crc & 1U)));
  }
  return crc ^ 0xffffffffU;
}

void append_u32(Bytes& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<std::uint8_t>(value >> shift));
}

void append_chunk(Bytes& out, const char* type, const Bytes& data) {
  append_u32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  append_u32(out, crc32(out.data() + start, out.size() - start));
}

// A zlib stream of one stored (uncompressed) deflate block, with its Adler-32 plus `adler_error`.
Bytes zlib_stored(const Bytes& raw, std::uint32_t adler_error = 0) {
  Bytes out = {0x78, 0x01, 0x01};
  const auto size = static_cast<std::uint16_t>(raw.size());
  out.push_back(static_cast<std::uint8_t>(size));
  out.push_back(static_cast<std::uint8_t>(size >> 8));
  out.push_back(static_cast<std::uint8_t>(~size));
  out.push_back(static_cast<std::uint8_t>(~size >> 8));
  out.insert(out.end(), raw.begin(), raw.end());
  std::uint32_t a = 1;
  std::uint32_t b = 0;
  for (const std::uint8_t byte : raw) {
    a = (a + byte) % 65521U;
    b = (b + a) % 65521U;
  }
  append_u32(out, ((b << 16) | a) + adler_error);
  return out;
}

Bytes make_png(std::uint32_t width, std::uint32_t height, std::uint8_t bit_depth,
               std::uint8_t colour_type, std::uint8_t interlace, const Bytes& idat) {
  Bytes out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  Bytes ihdr;
  append_u32(ihdr, width);
  append_u32(ihdr, height);
  ihdr.insert(ihdr.end(), {bit_depth, colour_type, 0, 0, interlace});
  append_chunk(out, "IHDR", ihdr);
  append_chunk(out, "IDAT", idat);
  append_chunk(out, "IEND", {});
  return out;
}

// The filtered rows (filter byte 0) of an 8x8 8-bit grey image of one `value`, Adam7-interlaced:
// passes of 1x1, 1x1, 2x1, 2x2, 4x2, 4x4 and 8x4 pixels.
Bytes interlaced_grey_8x8(std::uint8_t value) {
  Bytes raw;
  const int passes[7][2] = {{1, 1}, {1, 1}, {2, 1}, {2, 2}, {4, 2}, {4, 4}, {8, 4}};
  for (const auto& [width, height] : passes) {
    for (int row = 0; row < height; ++row) {
      raw.push_back(0);
      raw.insert(raw.end(), static_cast<std::size_t>(width), value);
    }
  }
  return raw;
}

facet::CameraIntrinsics camera(int width, int height) {
  facet::CameraIntrinsics intrinsics;
  intrinsics.fx = intrinsics.fy = 500.0;
  intrinsics.width = width;
  intrinsics.height = height;
  return intrinsics;
}

std::filesystem::path write(const TempDir& dir, const char* name, const Bytes& bytes) {
  facet::test::write_text(dir / name, std::string(bytes.begin(), bytes.end()));
  return dir / name;
}

TEST(PngHardening, ASizeThatIsNotTheCamerasIsRefusedBeforeDecoding) {
  TempDir dir;
  // 23170 x 23170 x 16 bit would be 1 GiB; the file holds a few bytes of image data.
  const auto bomb = write(dir, "bomb.png", make_png(23170, 23170, 16, 0, 0, zlib_stored({0})));
  expect_stage_error([&] { facet::io::read_depth_png(bomb, camera(640, 480)); },
                     {"bomb.png", "is 23170x23170 but the intrinsics say 640x480"});
  expect_stage_error([&] { facet::io::read_label_png(bomb, camera(640, 480)); },
                     {"bomb.png", "23170x23170"});
  const auto huge = write(dir, "huge.png", make_png(0x80000000U, 1, 8, 0, 0, zlib_stored({0})));
  expect_stage_error([&] { facet::io::read_depth_png(huge, camera(640, 480)); },
                     {"huge.png", "2147483648x1"});
}

TEST(PngHardening, ImageDataLongerThanTheHeaderSaysIsAnError) {
  // The rows of a 4x4 image behind the header of a 4x2 one: libpng tolerated it.
  Bytes rows(4 * 9, 0);
  for (std::size_t i = 0; i < rows.size(); ++i)
    rows[i] = static_cast<std::uint8_t>(i % 9);
  const Bytes longer = make_png(4, 2, 16, 0, 0, zlib_stored(rows));
  try {
    (void)png::decode(longer);
    ADD_FAILURE() << "expected png::FormatError";
  } catch (const png::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("longer than the header's 4x2 pixels"), std::string::npos)
        << e.what();
  }
  TempDir dir;
  const auto file = write(dir, "longer.png", longer);
  expect_stage_error([&] { facet::io::read_depth_png(file, camera(4, 2)); },
                     {"longer.png", "longer than the header"});
}

TEST(PngHardening, InterlacedPngsAreCheckedBeforeOpenCvDecodesThem) {
  TempDir dir;
  const Bytes raw = interlaced_grey_8x8(42);
  const auto good = write(dir, "good.png", make_png(8, 8, 8, 0, 1, zlib_stored(raw)));
  const cv::Mat labels = facet::io::read_label_png(good, camera(8, 8));
  EXPECT_EQ(cv::countNonZero(labels != 42), 0);

  // CRCs valid, the image data's Adler-32 wrong: libpng warns "incorrect data check" and goes on.
  const auto bad = write(dir, "bad.png", make_png(8, 8, 8, 0, 1, zlib_stored(raw, 1)));
  expect_stage_error([&] { facet::io::read_label_png(bad, camera(8, 8)); }, {"bad.png", "corrupt"});
  // One row short of what the seven passes need.
  const Bytes short_raw(raw.begin(), raw.end() - 9);
  const auto cut = write(dir, "short.png", make_png(8, 8, 8, 0, 1, zlib_stored(short_raw)));
  expect_stage_error([&] { facet::io::read_label_png(cut, camera(8, 8)); },
                     {"short.png", "shorter than the header's 8x8 pixels"});
}

TEST(PngHardening, PngsOfOtherKindsAreCheckedToo) {
  // 8-bit grey and alpha (colour type 4), 2x2: left to OpenCV, checked first. A sound one passes
  // the check and is refused only for what it is; a damaged one for its damage.
  const Bytes raw = {0, 10, 255, 20, 255, 0, 30, 255, 40, 255};
  TempDir dir;
  const auto good = write(dir, "alpha.png", make_png(2, 2, 8, 4, 0, zlib_stored(raw)));
  expect_stage_error([&] { facet::io::read_label_png(good, camera(2, 2)); },
                     {"alpha.png", "labels must be a single-channel"});
  const auto bad = write(dir, "alpha_bad.png", make_png(2, 2, 8, 4, 0, zlib_stored(raw, 7)));
  expect_stage_error([&] { facet::io::read_label_png(bad, camera(2, 2)); },
                     {"alpha_bad.png", "corrupt"});
  // A bit depth its colour type does not allow.
  const auto odd = write(dir, "odd.png", make_png(2, 2, 4, 4, 0, zlib_stored(raw)));
  expect_stage_error([&] { facet::io::read_label_png(odd, camera(2, 2)); },
                     {"odd.png", "colour type 4 at bit depth 4"});
}

TEST(PngHardening, OtherFormatsAreRefusedBeforeAnyDecoderSeesThem) {
  // A JPEG 2000 codestream of 97 bytes whose header declares 30000x30000 16-bit pixels: handed to
  // OpenCV, it allocated 1.8 GB before failing to decode.
  Bytes j2k = {0xff, 0x4f, 0xff, 0x51, 0x00, 0x29, 0x00, 0x00};
  for (int field = 0; field < 8; ++field)
    append_u32(j2k, field == 0 || field == 1 || field == 4 || field == 5 ? 30000U : 0U);
  j2k.insert(j2k.end(), {0x00, 0x01, 0x0f, 0x01, 0x01});
  j2k.insert(j2k.end(), {0xff, 0x52, 0x00, 0x0c, 0, 0, 0, 1, 0, 5, 4, 4, 0, 0});
  j2k.insert(j2k.end(), {0xff, 0x5c, 0x00, 0x04, 0x40, 0x48});
  j2k.insert(j2k.end(), {0xff, 0x90, 0x00, 0x0a, 0, 0, 0, 0, 0, 0, 0, 1, 0xff, 0x93});
  j2k.insert(j2k.end(), 16, 0);
  j2k.insert(j2k.end(), {0xff, 0xd9});
  ASSERT_EQ(j2k.size(), 97U);
  TempDir dir;
  const auto file = write(dir, "depth.png", j2k);
  expect_stage_error([&] { facet::io::read_depth_png(file, camera(640, 480)); },
                     {"depth.png", "not a PNG file"});
  expect_stage_error([&] { facet::io::read_label_png(file, camera(640, 480)); },
                     {"depth.png", "not a PNG file"});
}

}  // namespace
