// The PNG codec behind every depth, label and overlay file: what it writes reads back exactly,
// through itself and through OpenCV (libpng); what OpenCV writes it reads exactly; bad bytes are
// refused with a reason, and PNGs outside its subset are handed back to the general decoder.
#include "io/png_codec.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "io/png_files.hpp"

namespace {

namespace png = facet::io::png;
using Bytes = std::vector<std::uint8_t>;

bool equal(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  return cv::countNonZero(difference.reshape(1)) == 0;
}

// Noise over smooth ramps and flat runs: every filter's predictor gets left, up and up-left
// neighbours that differ, wrap around 8 bits and repeat.
cv::Mat test_image(int type, int width, int height, unsigned seed) {
  cv::Mat image(height, width, type);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, image.depth() == CV_16U ? 65536 : 256);
  for (int y = 0; y < height / 3; ++y)
    image.row(y).setTo(cv::Scalar::all(y * 37 % 251));
  return image;
}

Bytes opencv_encode(const cv::Mat& image, std::vector<int> params = {}) {
  Bytes bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes, params));
  return bytes;
}

struct Case {
  int type;
  png::Filter filter;
  png::Deflate deflate = png::Deflate::general;
};

class RoundTrip : public testing::TestWithParam<Case> {};

TEST_P(RoundTrip, ReadsBackExactlyThroughItselfAndOpenCV) {
  for (const cv::Size size : {cv::Size(1, 1), cv::Size(7, 5), cv::Size(64, 48), cv::Size(641, 3)}) {
    const cv::Mat image = test_image(GetParam().type, size.width, size.height, 11);
    const Bytes bytes =
        png::encode(image, {.filter = GetParam().filter, .deflate = GetParam().deflate});

    const std::optional<cv::Mat> ours = png::decode(bytes);
    ASSERT_TRUE(ours.has_value());
    EXPECT_TRUE(equal(*ours, image)) << size;
    EXPECT_TRUE(equal(cv::imdecode(bytes, cv::IMREAD_UNCHANGED), image)) << size;
  }
}

INSTANTIATE_TEST_SUITE_P(
    TypesAndFilters, RoundTrip,
    testing::Values(Case{CV_8UC1, png::Filter::none}, Case{CV_8UC1, png::Filter::sub},
                    Case{CV_8UC1, png::Filter::up}, Case{CV_8UC1, png::Filter::average},
                    Case{CV_8UC1, png::Filter::paeth}, Case{CV_16UC1, png::Filter::none},
                    Case{CV_16UC1, png::Filter::sub}, Case{CV_16UC1, png::Filter::up},
                    Case{CV_16UC1, png::Filter::average}, Case{CV_16UC1, png::Filter::paeth},
                    Case{CV_8UC3, png::Filter::sub}, Case{CV_8UC3, png::Filter::average},
                    Case{CV_8UC3, png::Filter::paeth},
                    Case{CV_8UC1, png::Filter::sub, png::Deflate::runs},
                    Case{CV_16UC1, png::Filter::sub, png::Deflate::runs},
                    Case{CV_16UC1, png::Filter::up, png::Deflate::runs},
                    Case{CV_8UC3, png::Filter::paeth, png::Deflate::runs}));

TEST(PngCodec, ReadsWhatOpenCVWritesWithEveryCompressionLevel) {
  // libpng picks a filter per row, so these files mix all five.
  for (const int type : {CV_8UC1, CV_16UC1, CV_8UC3}) {
    const cv::Mat image = test_image(type, 97, 61, 5);
    for (const int level : {0, 1, 9}) {
      const std::optional<cv::Mat> ours =
          png::decode(opencv_encode(image, {cv::IMWRITE_PNG_COMPRESSION, level}));
      ASSERT_TRUE(ours.has_value());
      EXPECT_TRUE(equal(*ours, image)) << "type " << type << ", level " << level;
    }
  }
}

TEST(PngCodec, ReadsTheBundledDepthFramesAsOpenCVDoes) {
  const std::filesystem::path dir = std::filesystem::path(FACET_TEST_DATA_DIR) / "mosd" / "depth";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".png" || files >= 5) continue;
    ++files;
    const cv::Mat reference = cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED);
    const facet::CameraIntrinsics camera{1, 1, 0, 0, reference.cols, reference.rows};
    EXPECT_TRUE(equal(facet::io::read_depth_png(entry.path(), camera), reference))
        << entry.path().filename();
  }
  EXPECT_EQ(files, 5);
}

TEST(PngCodec, CompressesFlatImages) {
  // A label image is mostly runs of one value; the fixed Sub filter must keep it small.
  cv::Mat labels(480, 640, CV_16UC1, cv::Scalar(0));
  labels(cv::Rect(100, 100, 200, 150)).setTo(3);
  EXPECT_LT(png::encode(labels).size(), 10'000u);
  EXPECT_LT(png::encode(labels, {.deflate = png::Deflate::runs}).size(), 10'000u);
}

TEST(PngCodec, HandsOtherKindsOfPngBack) {
  // Colour with alpha and 16-bit colour are valid PNGs outside the codec's subset.
  EXPECT_FALSE(png::decode(opencv_encode(cv::Mat(4, 4, CV_8UC4, cv::Scalar::all(9)))).has_value());
  EXPECT_FALSE(png::decode(opencv_encode(cv::Mat(4, 4, CV_16UC3, cv::Scalar::all(9)))).has_value());
}

TEST(PngCodec, RefusesMalformedBytesWithAReason) {
  const Bytes good = png::encode(test_image(CV_16UC1, 32, 32, 3));
  auto message = [](const Bytes& bytes) {
    try {
      (void)png::decode(bytes);
    } catch (const png::FormatError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };

  Bytes no_signature = good;
  no_signature[1] = 'Q';
  EXPECT_NE(message(no_signature).find("signature"), std::string::npos);

  Bytes corrupt = good;
  corrupt[good.size() / 2] ^= 0x40;  // inside IDAT
  EXPECT_NE(message(corrupt).find("CRC"), std::string::npos);

  const Bytes truncated(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(good.size() / 2));
  EXPECT_NE(message(truncated).find("truncated"), std::string::npos);

  const Bytes no_end(good.begin(), good.end() - 12);  // IEND removed
  EXPECT_NE(message(no_end).find("truncated"), std::string::npos);
}

TEST(PngCodec, RefusesImagesItCannotEncode) {
  EXPECT_THROW(png::encode(cv::Mat()), std::invalid_argument);
  EXPECT_THROW(png::encode(cv::Mat(2, 2, CV_32FC1)), std::invalid_argument);
}

}  // namespace
