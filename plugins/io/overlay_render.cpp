#include "io/overlay_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace facet::io {
namespace {

// Valid depth maps to grey kFarGrey (far) .. 255 (near); invalid depth is 0, so the farthest
// valid depth stays visibly different from no measurement.
constexpr int kFarGrey = 48;
constexpr double kLowPercentile = 0.01;
constexpr double kHighPercentile = 0.99;

// Grey of a valid depth `z_m` in [near, far]; closer is brighter.
std::uint8_t grey_of(double z_m, const GreyRange& range) {
  const double span = range.far_m - range.near_m;
  if (span <= 0.0 || z_m <= range.near_m) return 255;
  if (z_m >= range.far_m) return kFarGrey;
  const double t = (range.far_m - z_m) / span;  // 1 at near, 0 at far
  return static_cast<std::uint8_t>(std::lround(kFarGrey + t * (255 - kFarGrey)));
}

// Millimetres of a metre depth, or 0 when it is not a measurement; saturates at 65535.
std::uint16_t millimetres(float z_m) {
  if (!(z_m > 0.0F) || !std::isfinite(z_m)) return 0;
  const float mm = std::round(z_m * 1000.0F);
  return mm >= 65535.0F ? std::uint16_t{65535} : static_cast<std::uint16_t>(std::max(mm, 1.0F));
}

// The grey of every pixel (0 = invalid), CV_8UC1.
cv::Mat grey_image(const cv::Mat& depth, const GreyRange& range) {
  cv::Mat grey(depth.size(), CV_8UC1);
  if (depth.type() == CV_16UC1) {
    std::vector<std::uint8_t> lut(65536);
    lut[0] = 0;
    // Every depth from `far` on is kFarGrey: those entries, all but the first metre or two of the
    // table's 65 m, are filled at once instead of through grey_of's rounding one by one.
    const bool has_span = range.far_m - range.near_m > 0.0;
    for (std::size_t mm = 1; mm < lut.size(); ++mm) {
      const double z_m = static_cast<double>(mm) * 0.001;
      if (has_span && z_m >= range.far_m) {
        std::fill(lut.begin() + static_cast<std::ptrdiff_t>(mm), lut.end(),
                  static_cast<std::uint8_t>(kFarGrey));
        break;
      }
      lut[mm] = grey_of(z_m, range);
    }
    for (int y = 0; y < depth.rows; ++y) {
      const auto* src = depth.ptr<std::uint16_t>(y);
      auto* dst = grey.ptr<std::uint8_t>(y);
      for (int x = 0; x < depth.cols; ++x)
        dst[x] = lut[src[x]];
    }
    return grey;
  }
  for (int y = 0; y < depth.rows; ++y) {
    const auto* src = depth.ptr<float>(y);
    auto* dst = grey.ptr<std::uint8_t>(y);
    for (int x = 0; x < depth.cols; ++x) {
      const float z = src[x];
      dst[x] = z > 0.0F && std::isfinite(z) ? grey_of(z, range) : std::uint8_t{0};
    }
  }
  return grey;
}

// Segment colours: label_colour() is computed once per run of equal ids along a row.
class ColourMemo {
 public:
  const Rgb& operator()(std::int32_t id) {
    if (id != id_) {
      id_ = id;
      colour_ = label_colour(static_cast<std::uint32_t>(id));
    }
    return colour_;
  }

 private:
  std::int32_t id_ = 0;
  Rgb colour_{};
};

bool is_border(const std::int32_t* up, const std::int32_t* row, const std::int32_t* down, int x,
               int cols) {
  const std::int32_t id = row[x];
  return (x > 0 && row[x - 1] != id) || (x + 1 < cols && row[x + 1] != id) ||
         (up != nullptr && up[x] != id) || (down != nullptr && down[x] != id);
}

void put(cv::Vec3b& pixel, const Rgb& colour) {
  pixel = cv::Vec3b(colour.b, colour.g, colour.r);
}

}  // namespace

GreyRange auto_grey_range(const cv::Mat& depth) {
  CV_Assert(depth.type() == CV_16UC1 || depth.type() == CV_32FC1);
  std::vector<std::uint32_t> histogram(65536, 0);
  std::uint64_t valid = 0;
  for (int y = 0; y < depth.rows; ++y) {
    if (depth.type() == CV_16UC1) {
      const auto* src = depth.ptr<std::uint16_t>(y);
      for (int x = 0; x < depth.cols; ++x)
        ++histogram[src[x]];
    } else {
      const auto* src = depth.ptr<float>(y);
      for (int x = 0; x < depth.cols; ++x)
        ++histogram[millimetres(src[x])];
    }
  }
  histogram[0] = 0;  // no measurement
  for (const std::uint32_t count : histogram)
    valid += count;
  if (valid == 0) return {};
  // The k-th smallest valid depth (k from 0) at the two percentiles.
  const auto rank_low = static_cast<std::uint64_t>(kLowPercentile * static_cast<double>(valid - 1));
  const auto rank_high =
      static_cast<std::uint64_t>(std::ceil(kHighPercentile * static_cast<double>(valid - 1)));
  GreyRange range;
  std::uint64_t seen = 0;
  bool low_found = false;
  for (std::size_t mm = 1; mm < histogram.size(); ++mm) {
    seen += histogram[mm];
    if (!low_found && seen > rank_low) {
      range.near_m = static_cast<double>(mm) * 0.001;
      low_found = true;
    }
    if (seen > rank_high) {
      range.far_m = static_cast<double>(mm) * 0.001;
      break;
    }
  }
  return range;
}

cv::Mat render_overlay(const cv::Mat& depth, const cv::Mat& labels, const cv::Mat& edge_mask,
                       const OverlayStyle& style, ParallelRunner* runner) {
  CV_Assert(depth.type() == CV_16UC1 || depth.type() == CV_32FC1);
  CV_Assert(labels.empty() || (labels.type() == CV_32SC1 && labels.size() == depth.size()));
  CV_Assert(edge_mask.empty() || (edge_mask.type() == CV_8UC1 && edge_mask.size() == depth.size()));
  const GreyRange range =
      style.far_m > 0.0 ? GreyRange{style.near_m, style.far_m} : auto_grey_range(depth);
  const cv::Mat grey = grey_image(depth, range);
  const int weight = static_cast<int>(std::lround(std::clamp(style.alpha, 0.0, 1.0) * 256.0));
  const bool edges = style.draw_edges && !edge_mask.empty();
  const int rows = depth.rows;
  const int cols = depth.cols;

  cv::Mat out(depth.size(), CV_8UC3);
  constexpr std::int64_t kMinBandRows = 32;
  parallel_for(runner, rows, kMinBandRows, [&](std::int64_t band_begin, std::int64_t band_end) {
    ColourMemo colour_of;
    for (int y = static_cast<int>(band_begin); y < static_cast<int>(band_end); ++y) {
      const auto* g = grey.ptr<std::uint8_t>(y);
      auto* dst = out.ptr<cv::Vec3b>(y);
      const std::int32_t* ids = labels.empty() ? nullptr : labels.ptr<std::int32_t>(y);
      const std::int32_t* up = ids != nullptr && y > 0 ? labels.ptr<std::int32_t>(y - 1) : nullptr;
      const std::int32_t* down =
          ids != nullptr && y + 1 < rows ? labels.ptr<std::int32_t>(y + 1) : nullptr;
      const std::uint8_t* mask = edges ? edge_mask.ptr<std::uint8_t>(y) : nullptr;
      for (int x = 0; x < cols; ++x) {
        const int base = g[x] * (256 - weight);
        if (ids == nullptr || ids[x] == 0) {
          dst[x] = cv::Vec3b(g[x], g[x], g[x]);
        } else {
          const Rgb& c = colour_of(ids[x]);
          dst[x] = cv::Vec3b(static_cast<std::uint8_t>((base + c.b * weight) >> 8),
                             static_cast<std::uint8_t>((base + c.g * weight) >> 8),
                             static_cast<std::uint8_t>((base + c.r * weight) >> 8));
        }
        // Edge stages mark pixels without depth as edges too; those stay black.
        if (mask != nullptr && mask[x] != 0 && g[x] != 0) put(dst[x], style.edge_colour);
        if (style.draw_borders && ids != nullptr && ids[x] != 0 &&
            is_border(up, ids, down, x, cols)) {
          put(dst[x], style.border_colour);
        }
      }
    }
  });
  return out;
}

}  // namespace facet::io
