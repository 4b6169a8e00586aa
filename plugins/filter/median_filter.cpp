#include "filter/median_filter.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace facet::filters {
namespace {

const In<DepthImage> kDepthIn{"depth",
                              "Depth image, CV_16UC1 in mm (0 = invalid) or CV_32FC1 in m "
                              "(0 or NaN = invalid)."};
const Out<DepthImage> kDepthOut{"depth",
                                "Filtered depth, same type, size and header as the input."};
const Param<int> kSize{"size",
                       3,
                       "Side length of the square window.",
                       {.unit = "px",
                        .choices = {std::int64_t{3}, std::int64_t{5}},
                        .origin = "3 removes single-pixel speckle of structured-light sensors "
                                  "while keeping object edges sharp; 5 also smooths quantisation "
                                  "steps"}};
const Param<bool> kFillHoles{"fill_holes",
                             false,
                             "Give an invalid pixel the median of its window when more than half "
                             "of the window is valid (closes pinholes; off keeps every hole as "
                             "measured).",
                             {.origin = "off: later stages should see only measured depth"}};
const Param<double> kMaxPinholeRatio{
    "max_pinhole_ratio",
    0.005,
    "With fill_holes off, warn when more than this share of the valid pixels are "
    "pinholes: invalid pixels whose four neighbours are valid (sampled on every 4th "
    "row; also the metric pinhole_ratio). Each pinhole breaks the surfaces around it "
    "into fragments; fill_holes closes them. 1 never warns.",
    {.unit = "fraction",
     .min = 0.0,
     .max = 1.0,
     .origin = "measured: the bundled mOSD and YCB-Video frames have under 0.01 %; "
               "from 1 % on, synthetic tabletop frames lose objects"}};

// Pinholes are sampled on every kPinholeRowStep-th row: the count only feeds a metric and a
// warning, and a quarter of the rows costs a fraction of the filter itself.
constexpr int kPinholeRowStep = 4;

inline bool valid_depth(std::uint16_t value) {
  return value != 0;
}
inline bool valid_depth(float value) {
  return value > 0.0F && std::isfinite(value);
}

struct PinholeCount {
  std::int64_t pinholes = 0;  // invalid pixels whose 4 direct neighbours are all valid
  std::int64_t valid = 0;     // valid pixels of the same rows
};

template <class T>
PinholeCount count_pinholes(const cv::Mat& depth) {
  PinholeCount count;
  for (int y = 1; y + 1 < depth.rows; y += kPinholeRowStep) {
    const T* up = depth.ptr<T>(y - 1);
    const T* row = depth.ptr<T>(y);
    const T* down = depth.ptr<T>(y + 1);
    unsigned pinholes = 0;
    unsigned valid = valid_depth(row[0]) ? 1U : 0U;
    if (depth.cols > 1 && valid_depth(row[depth.cols - 1])) ++valid;
    for (int x = 1; x + 1 < depth.cols; ++x) {
      const bool here = valid_depth(row[x]);
      valid += here ? 1U : 0U;
      pinholes += static_cast<unsigned>(!here & valid_depth(row[x - 1]) & valid_depth(row[x + 1]) &
                                        valid_depth(up[x]) & valid_depth(down[x]));
    }
    count.pinholes += pinholes;
    count.valid += valid;
  }
  return count;
}

}  // namespace

StageSpec MedianFilter::spec() {
  StageSpec spec("filter.median",
                 "Median filter over the valid pixels of each window.\n"
                 "Invalid pixels (0, NaN) are ignored: they never pull a median towards zero. "
                 "A pixel that is itself invalid stays invalid unless fill_holes is set, so "
                 "the filter removes noise without inventing depth in holes. Pixels outside "
                 "the image count as invalid. With an even number of valid values the lower "
                 "middle value is taken, so every output is a measured depth.");
  return spec.declare(kDepthIn, kDepthOut, kSize, kFillHoles, kMaxPinholeRatio)
      .concurrency(Concurrency::clonable);
}

MedianFilter::MedianFilter(const Params& params)
    : median_(kSize(params), kFillHoles(params)), max_pinhole_ratio_(kMaxPinholeRatio(params)) {}

void MedianFilter::process(ProcessContext& ctx) {
  const DepthImage& input = kDepthIn(ctx);
  cv::Mat filtered;
  try {
    filtered = median_.apply(input.depth);
  } catch (const std::invalid_argument& error) {
    throw StageError(error.what());
  }
  if (!median_.fill_holes()) warn_about_pinholes(input.depth, ctx);
  kDepthOut(ctx, DepthImage::make(input, std::move(filtered)));
}

void MedianFilter::warn_about_pinholes(const cv::Mat& depth, ProcessContext& ctx) const {
  const PinholeCount count = depth.type() == CV_16UC1 ? count_pinholes<std::uint16_t>(depth)
                                                      : count_pinholes<float>(depth);
  const double ratio = count.valid > 0
                           ? static_cast<double>(count.pinholes) / static_cast<double>(count.valid)
                           : 0.0;
  ctx.metric("pinhole_ratio", ratio);
  if (ratio <= max_pinhole_ratio_) return;
  char percent[32];
  std::snprintf(percent, sizeof percent, "%.1f %%", 100.0 * ratio);
  ctx.warn(std::string(percent) +
           " of the valid pixels are pinholes (single pixels without depth): they break "
           "surfaces into fragments, which become spurious objects or hide the table; "
           "fill_holes: true closes them");
}

}  // namespace facet::filters
