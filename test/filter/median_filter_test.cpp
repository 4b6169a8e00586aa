// filter.median against a straightforward reference, and the rules about invalid pixels.
#include "filter/median_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "filter/sorting_network.hpp"
#include "filter/valid_median.hpp"

namespace {

using facet::filters::ValidMedian;

bool is_valid(float v) {
  return v > 0.0F && std::isfinite(v);
}
bool is_valid(std::uint16_t v) {
  return v != 0;
}

// The definition, written for clarity: collect the valid pixels of the window inside the
// image, take the lower median.
template <class T>
cv::Mat reference_median(const cv::Mat& depth, int size, bool fill_holes) {
  const int r = size / 2;
  cv::Mat out = depth.clone();
  std::vector<T> values;
  for (int y = 0; y < depth.rows; ++y) {
    for (int x = 0; x < depth.cols; ++x) {
      values.clear();
      for (int v = std::max(0, y - r); v <= std::min(depth.rows - 1, y + r); ++v) {
        for (int u = std::max(0, x - r); u <= std::min(depth.cols - 1, x + r); ++u) {
          if (is_valid(depth.at<T>(v, u))) values.push_back(depth.at<T>(v, u));
        }
      }
      const bool centre_valid = is_valid(depth.at<T>(y, x));
      const bool fill = fill_holes && 2 * static_cast<int>(values.size()) > size * size;
      if (values.empty() || (!centre_valid && !fill)) continue;
      std::sort(values.begin(), values.end());
      out.at<T>(y, x) = values[(values.size() - 1) / 2];
    }
  }
  return out;
}

// Depth 400-2000 mm with a share of holes: scattered pixels and whole blocks.
cv::Mat random_depth_mm(int width, int height, double hole_share, std::uint64_t seed) {
  cv::RNG rng(seed);
  cv::Mat depth(height, width, CV_16UC1);
  rng.fill(depth, cv::RNG::UNIFORM, 400, 2001);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (rng.uniform(0.0, 1.0) < hole_share) depth.at<std::uint16_t>(y, x) = 0;
    }
  }
  for (int i = 0; i < 3; ++i) {
    const int x = rng.uniform(0, width);
    const int y = rng.uniform(0, height);
    depth(cv::Rect(x, y, std::min(7, width - x), std::min(5, height - y))).setTo(0);
  }
  return depth;
}

cv::Mat to_metres_with_nans(const cv::Mat& depth_mm, std::uint64_t seed) {
  cv::Mat metres;
  depth_mm.convertTo(metres, CV_32F, 0.001);
  cv::RNG rng(seed);
  for (int y = 0; y < metres.rows; ++y) {
    for (int x = 0; x < metres.cols; ++x) {
      float& v = metres.at<float>(y, x);
      if (v == 0.0F && rng.uniform(0, 2) == 0) v = std::numeric_limits<float>::quiet_NaN();
    }
  }
  return metres;
}

// Equal pixel for pixel; NaN equals NaN.
::testing::AssertionResult same_image(const cv::Mat& actual, const cv::Mat& expected) {
  if (actual.size() != expected.size() || actual.type() != expected.type()) {
    return ::testing::AssertionFailure() << "size or type differs";
  }
  for (int y = 0; y < actual.rows; ++y) {
    for (int x = 0; x < actual.cols; ++x) {
      if (actual.type() == CV_16UC1) {
        if (actual.at<std::uint16_t>(y, x) != expected.at<std::uint16_t>(y, x)) {
          return ::testing::AssertionFailure()
                 << "at (" << x << ", " << y << "): " << actual.at<std::uint16_t>(y, x)
                 << " != " << expected.at<std::uint16_t>(y, x);
        }
      } else {
        const float a = actual.at<float>(y, x);
        const float e = expected.at<float>(y, x);
        if (!(a == e || (std::isnan(a) && std::isnan(e)))) {
          return ::testing::AssertionFailure()
                 << "at (" << x << ", " << y << "): " << a << " != " << e;
        }
      }
    }
  }
  return ::testing::AssertionSuccess();
}

// size, fill_holes, width, height, hole share
using Case = std::tuple<int, bool, int, int, double>;

class MedianMatchesReference : public ::testing::TestWithParam<Case> {};

TEST_P(MedianMatchesReference, Millimetres) {
  const auto [size, fill, width, height, holes] = GetParam();
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const cv::Mat depth = random_depth_mm(width, height, holes, seed);
    ValidMedian median(size, fill);
    EXPECT_TRUE(same_image(median.apply(depth), reference_median<std::uint16_t>(depth, size, fill)))
        << "seed " << seed;
  }
}

TEST_P(MedianMatchesReference, MetresWithNaNs) {
  const auto [size, fill, width, height, holes] = GetParam();
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const cv::Mat depth = to_metres_with_nans(random_depth_mm(width, height, holes, seed), seed);
    ValidMedian median(size, fill);
    EXPECT_TRUE(same_image(median.apply(depth), reference_median<float>(depth, size, fill)))
        << "seed " << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(SizesShapesAndHoles, MedianMatchesReference,
                         ::testing::Combine(::testing::Values(3, 5), ::testing::Bool(),
                                            ::testing::Values(1, 2, 17, 64, 161),
                                            ::testing::Values(1, 3, 40),
                                            ::testing::Values(0.0, 0.2, 0.6)));

TEST(ValidMedian, FullVgaFrameMatchesReference) {
  const cv::Mat depth = random_depth_mm(640, 480, 0.3, 11);
  for (int size : {3, 5}) {
    ValidMedian median(size, false);
    EXPECT_TRUE(
        same_image(median.apply(depth), reference_median<std::uint16_t>(depth, size, false)));
    // A second frame through the same object reuses its buffers.
    const cv::Mat other = random_depth_mm(640, 480, 0.1, 12);
    EXPECT_TRUE(
        same_image(median.apply(other), reference_median<std::uint16_t>(other, size, false)));
  }
}

// The scratch buffers are laid out again whenever the frame size changes, also when the new
// size needs as many padded values as the old one (16x15 then 32x7 at 3x3: the border lies
// elsewhere) or the same padded row length (16 then 10 columns: columns 10-15 are outside the
// new image). Stale values there once leaked into the medians at the image border.
TEST(ValidMedian, AReusedInstanceMatchesTheReferenceAcrossFrameSizes) {
  const std::vector<cv::Size> sizes = {{16, 15}, {32, 7}, {16, 6}, {10, 6}, {40, 40}, {3, 2}};
  for (int size : {3, 5}) {
    for (bool fill : {false, true}) {
      ValidMedian median(size, fill);
      std::uint64_t seed = 20;
      for (const cv::Size frame : sizes) {
        SCOPED_TRACE(::testing::Message() << size << "x" << size << (fill ? " fill " : " ")
                                          << frame.width << "x" << frame.height);
        const cv::Mat depth = random_depth_mm(frame.width, frame.height, 0.3, ++seed);
        EXPECT_TRUE(
            same_image(median.apply(depth), reference_median<std::uint16_t>(depth, size, fill)));
        const cv::Mat metres = to_metres_with_nans(depth, ++seed);
        EXPECT_TRUE(same_image(median.apply(metres), reference_median<float>(metres, size, fill)));
      }
    }
  }
}

TEST(ValidMedian, ZerosNeverPullTheMedianDown) {
  // Five holes and four measurements of 1000 mm around a valid centre: cv::medianBlur gives 0.
  cv::Mat depth = (cv::Mat_<std::uint16_t>(3, 3) << 0, 1000, 0, 1000, 1000, 0, 0, 1000, 0);
  EXPECT_EQ(ValidMedian(3, false).apply(depth).at<std::uint16_t>(1, 1), 1000);
}

TEST(ValidMedian, HolesAreNeverFilledByDefault) {
  cv::Mat depth(9, 9, CV_16UC1, cv::Scalar(800));
  depth.at<std::uint16_t>(4, 4) = 0;     // a single hole surrounded by valid depth
  depth(cv::Rect(0, 0, 3, 3)).setTo(0);  // a corner block
  for (int size : {3, 5}) {
    const cv::Mat out = ValidMedian(size, false).apply(depth);
    EXPECT_EQ(cv::countNonZero((out == 0) != (depth == 0)), 0) << "size " << size;
    EXPECT_EQ(out.at<std::uint16_t>(4, 4), 0);
  }
}

TEST(ValidMedian, FillHolesNeedsAValidMajority) {
  cv::Mat depth(7, 7, CV_16UC1, cv::Scalar(800));
  depth.at<std::uint16_t>(3, 3) = 0;     // 8 of 9 valid: filled
  depth(cv::Rect(0, 0, 2, 7)).setTo(0);  // left edge column 0: at (0, 3) only 2 of 6 valid
  const cv::Mat out = ValidMedian(3, true).apply(depth);
  EXPECT_EQ(out.at<std::uint16_t>(3, 3), 800);
  EXPECT_EQ(out.at<std::uint16_t>(3, 0), 0);
  // Column 1 has 3 of 9 valid neighbours: stays a hole.
  EXPECT_EQ(out.at<std::uint16_t>(3, 1), 0);
}

TEST(ValidMedian, FloatHolesKeepTheirValue) {
  cv::Mat depth(5, 5, CV_32FC1, cv::Scalar(1.5F));
  depth.at<float>(1, 1) = std::numeric_limits<float>::quiet_NaN();
  depth.at<float>(3, 3) = 0.0F;
  depth.at<float>(2, 2) = 1.4F;
  const cv::Mat out = ValidMedian(3, false).apply(depth);
  EXPECT_TRUE(std::isnan(out.at<float>(1, 1)));
  EXPECT_EQ(out.at<float>(3, 3), 0.0F);
  EXPECT_EQ(out.at<float>(2, 2), 1.5F);  // NaN and 0 in its window are ignored
  EXPECT_EQ(out.at<float>(0, 0), 1.5F);
}

TEST(ValidMedian, BorderWindowsUseOnlyPixelsInsideTheImage) {
  // Corner (0,0) sees 4 pixels {100, 200, 300, 400}: lower median 200, not a padded value.
  cv::Mat depth = (cv::Mat_<std::uint16_t>(3, 3) << 100, 200, 900, 300, 400, 900, 900, 900, 900);
  const cv::Mat out = ValidMedian(3, false).apply(depth);
  EXPECT_EQ(out.at<std::uint16_t>(0, 0), 200);
  EXPECT_EQ(out.at<std::uint16_t>(2, 2), 900);
  // Top edge (1, 0) sees {100, 200, 900, 300, 400, 900}: lower median 300.
  EXPECT_EQ(out.at<std::uint16_t>(0, 1), 300);
}

TEST(ValidMedian, RejectsUnsupportedSizesAndTypes) {
  EXPECT_THROW(ValidMedian(4, false), std::invalid_argument);
  EXPECT_THROW(ValidMedian(3, false).apply(cv::Mat(4, 4, CV_8UC1)), std::invalid_argument);
}

TEST(SortingNetwork, SortsEveryZeroOneInputOfNine) {
  constexpr auto network = facet::filters::sorting_network<9>();
  for (unsigned bits = 0; bits < (1U << 9); ++bits) {
    int v[9];
    for (int i = 0; i < 9; ++i)
      v[i] = static_cast<int>((bits >> i) & 1U);
    for (const auto c : network) {
      if (v[c.low] > v[c.high]) std::swap(v[c.low], v[c.high]);
    }
    ASSERT_TRUE(std::is_sorted(std::begin(v), std::end(v))) << bits;
  }
}

TEST(MedianFilterStage, KeepsTheHeaderAndRejectsOtherSizes) {
  facet::testing::StageRunner<facet::filters::MedianFilter> runner({{"size", std::int64_t{5}}});
  facet::DepthImage input;
  input.frame.stem = "learn0";
  input.frame.index = 3;
  input.camera.fx = 525.0;
  input.depth = random_depth_mm(32, 24, 0.2, 5);
  runner.set_input("depth", facet::Packet::make(input));
  runner.run();
  const auto& out = runner.output<facet::DepthImage>("depth");
  EXPECT_EQ(out.frame.stem, "learn0");
  EXPECT_EQ(out.frame.index, 3);
  EXPECT_EQ(out.camera.fx, 525.0);
  EXPECT_TRUE(same_image(out.depth, reference_median<std::uint16_t>(input.depth, 5, false)));

  using Runner = facet::testing::StageRunner<facet::filters::MedianFilter>;
  EXPECT_THROW(Runner({{"size", std::int64_t{4}}}), std::invalid_argument);
}

double metric_value(const std::vector<facet::Metric>& metrics, const std::string& name) {
  for (const auto& metric : metrics) {
    if (metric.name == name) return metric.value;
  }
  ADD_FAILURE() << "no metric " << name;
  return -1.0;
}

// Single pixels without depth (2 % of a VGA frame) break surfaces into fragments downstream: the
// stage says so and names the remedy, unless it fills them itself. Large holes (a cropped
// background) and the few pinholes of real frames are no reason to warn.
TEST(MedianFilterStage, WarnsAboutPinholesUnlessItFillsThem) {
  using Runner = facet::testing::StageRunner<facet::filters::MedianFilter>;
  auto run = [](Runner& runner, const cv::Mat& depth) {
    facet::DepthImage input;
    input.depth = depth;
    runner.set_input("depth", facet::Packet::make(input));
    runner.run();
  };
  cv::Mat pinholes = random_depth_mm(640, 480, 0.02, 3);
  Runner plain;
  run(plain, pinholes);
  ASSERT_EQ(plain.warnings().size(), 1U);
  EXPECT_NE(plain.warnings()[0].find("pinholes"), std::string::npos) << plain.warnings()[0];
  EXPECT_NE(plain.warnings()[0].find("fill_holes: true"), std::string::npos) << plain.warnings()[0];
  EXPECT_NEAR(metric_value(plain.metrics(), "pinhole_ratio"), 0.02 * 0.98 * 0.98 * 0.98 * 0.98,
              0.004);

  Runner filling({{"fill_holes", true}});
  run(filling, pinholes);
  EXPECT_TRUE(filling.warnings().empty());

  Runner tolerant({{"max_pinhole_ratio", 0.05}});
  run(tolerant, pinholes);
  EXPECT_TRUE(tolerant.warnings().empty());

  cv::Mat cropped = random_depth_mm(640, 480, 0.0, 4);
  cropped.rowRange(0, 200).setTo(0);
  cropped.colRange(500, 640).setTo(0);
  Runner quiet;
  run(quiet, cropped);
  EXPECT_TRUE(quiet.warnings().empty());
  EXPECT_EQ(metric_value(quiet.metrics(), "pinhole_ratio"), 0.0);

  // Float metres: NaN is no depth either.
  cv::Mat metres(480, 640, CV_32FC1, cv::Scalar(1.0F));
  for (int y = 0; y < 480; ++y) {
    for (int x = 1 + 10 * (y % 2); x < 640; x += 20)
      metres.at<float>(y, x) = std::numeric_limits<float>::quiet_NaN();
  }
  Runner floats;
  run(floats, metres);
  EXPECT_EQ(floats.warnings().size(), 1U);

  // Frames too small for a pinhole (no pixel has four neighbours) are no error.
  Runner tiny;
  run(tiny, cv::Mat(2, 1, CV_16UC1, cv::Scalar(0)));
  EXPECT_TRUE(tiny.warnings().empty());
}

TEST(MedianFilterStage, SpecDocumentsEveryPortAndParameter) {
  const facet::StageSpec spec = facet::filters::MedianFilter::spec();
  EXPECT_EQ(spec.name(), "filter.median");
  EXPECT_FALSE(spec.summary().empty());
  EXPECT_EQ(spec.concurrency(), facet::Concurrency::clonable);
  for (const auto& port : spec.inputs())
    EXPECT_FALSE(port.doc.empty()) << port.name;
  for (const auto& port : spec.outputs())
    EXPECT_FALSE(port.doc.empty()) << port.name;
  for (const auto& param : spec.params()) {
    EXPECT_FALSE(param.doc.empty()) << param.name;
    if (param.type == facet::ParamType::integer || param.type == facet::ParamType::real) {
      EXPECT_FALSE(param.options.unit.empty()) << param.name << " has no unit";
    }
  }
  ASSERT_NE(spec.find_param("size"), nullptr);
  EXPECT_EQ(spec.find_param("size")->options.choices.size(), 2U);
}

}  // namespace
