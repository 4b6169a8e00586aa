#include "filter/valid_median.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "filter/median_kernel.hpp"

namespace facet::filters {
namespace {

int round_up(int value, int multiple) {
  return (value + multiple - 1) / multiple * multiple;
}

// The image copied into a buffer with a border of `radius` invalid pixels on every side and the
// rows widened to whole vectors, so the kernel reads every window without bounds checks.
struct PaddedGeometry {
  int radius = 0;
  int width_padded = 0;  // output width rounded up to whole vectors
  int stride = 0;        // values per padded row
  int rows = 0;

  PaddedGeometry(const cv::Mat& image, int size, int lanes)
      : radius(size / 2),
        width_padded(round_up(image.cols, lanes)),
        stride(width_padded + 2 * radius),
        rows(image.rows + 2 * radius) {}

  std::size_t total() const { return static_cast<std::size_t>(stride) * rows; }
  std::size_t offset(int y, int x) const {
    return static_cast<std::size_t>(y + radius) * stride + static_cast<std::size_t>(x + radius);
  }
};

// Lays `buffer` out for an image of `size`: all invalid, written only when the image size
// changes, since each frame overwrites exactly the interior. (Comparing the buffer's length
// would not do: images of other sizes can need as many values, with the border and the columns
// beyond the image elsewhere.)
template <class Scalar>
void prepare(std::vector<Scalar>& buffer, cv::Size& prepared_for, cv::Size size, std::size_t total,
             Scalar invalid) {
  if (buffer.size() == total && prepared_for == size) return;
  buffer.assign(total, invalid);
  prepared_for = size;
}

}  // namespace

ValidMedian::ValidMedian(int size_px, bool fill_holes)
    : size_px_(size_px), fill_holes_(fill_holes) {
  if (size_px != 3 && size_px != 5) throw std::invalid_argument("median size must be 3 or 5 px");
}

cv::Mat ValidMedian::apply(const cv::Mat& depth) {
  if (depth.channels() != 1) throw std::invalid_argument("depth image must have one channel");
  if (depth.type() == CV_16UC1) return apply_u16(depth);
  if (depth.type() == CV_32FC1) return apply_f32(depth);
  throw std::invalid_argument("depth image must be CV_16UC1 (mm) or CV_32FC1 (m)");
}

// Millimetres are shifted into signed 16-bit (v ^ 0x8000) so that 0 becomes the lowest value and
// min/max are single signed instructions even on the x86-64 baseline.
cv::Mat ValidMedian::apply_u16(const cv::Mat& depth) {
  constexpr std::uint16_t kBias = 0x8000;
  const PaddedGeometry geometry(depth, size_px_, kMedianLanesI16);
  prepare(padded_u16_, padded_u16_for_, depth.size(), geometry.total(),
          std::numeric_limits<std::int16_t>::min());
  row_u16_.resize(static_cast<std::size_t>(geometry.width_padded));

  for (int y = 0; y < depth.rows; ++y) {
    const auto* src = depth.ptr<std::uint16_t>(y);
    std::int16_t* dst = padded_u16_.data() + geometry.offset(y, 0);
    for (int x = 0; x < depth.cols; ++x)
      dst[x] = static_cast<std::int16_t>(src[x] ^ kBias);
  }

  cv::Mat result(depth.size(), CV_16UC1);
  const std::int16_t* rows[5] = {};
  for (int y = 0; y < depth.rows; ++y) {
    for (int dy = 0; dy < size_px_; ++dy) {
      rows[dy] = padded_u16_.data() + geometry.offset(y + dy - geometry.radius, -geometry.radius);
    }
    median_row_i16(rows, row_u16_.data(), geometry.width_padded, size_px_, fill_holes_);
    auto* out = result.ptr<std::uint16_t>(y);
    for (int x = 0; x < depth.cols; ++x) {
      out[x] = static_cast<std::uint16_t>(static_cast<std::uint16_t>(row_u16_[x]) ^ kBias);
    }
  }
  return result;
}

// Metres: invalid values (0, negative, NaN, infinite) become -inf for the kernel; an output that
// is still invalid gets the original input value back, so NaN stays NaN and 0 stays 0.
cv::Mat ValidMedian::apply_f32(const cv::Mat& depth) {
  constexpr float kInvalid = -std::numeric_limits<float>::infinity();
  const PaddedGeometry geometry(depth, size_px_, kMedianLanesF32);
  prepare(padded_f32_, padded_f32_for_, depth.size(), geometry.total(), kInvalid);
  row_f32_.resize(static_cast<std::size_t>(geometry.width_padded));

  for (int y = 0; y < depth.rows; ++y) {
    const auto* src = depth.ptr<float>(y);
    float* dst = padded_f32_.data() + geometry.offset(y, 0);
    for (int x = 0; x < depth.cols; ++x) {
      const float v = src[x];
      dst[x] = (v > 0.0F && v < std::numeric_limits<float>::infinity()) ? v : kInvalid;
    }
  }

  cv::Mat result(depth.size(), CV_32FC1);
  const float* rows[5] = {};
  for (int y = 0; y < depth.rows; ++y) {
    for (int dy = 0; dy < size_px_; ++dy) {
      rows[dy] = padded_f32_.data() + geometry.offset(y + dy - geometry.radius, -geometry.radius);
    }
    median_row_f32(rows, row_f32_.data(), geometry.width_padded, size_px_, fill_holes_);
    const auto* src = depth.ptr<float>(y);
    auto* out = result.ptr<float>(y);
    for (int x = 0; x < depth.cols; ++x)
      out[x] = row_f32_[x] == kInvalid ? src[x] : row_f32_[x];
  }
  return result;
}

}  // namespace facet::filters
