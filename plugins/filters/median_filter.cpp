#include "filters/median_filter.hpp"

#include <stdexcept>

#include "facet/types/images.hpp"

namespace facet::filters {

StageSpec MedianFilter::spec() {
  return StageSpec("filter.median",
                   "Median filter over the valid pixels of each window.\n"
                   "Invalid pixels (0, NaN) are ignored: they never pull a median towards zero. "
                   "A pixel that is itself invalid stays invalid unless fill_holes is set, so "
                   "the filter removes noise without inventing depth in holes. Pixels outside "
                   "the image count as invalid. With an even number of valid values the lower "
                   "middle value is taken, so every output is a measured depth.")
      .input<DepthImage>("depth",
                         "Depth image, CV_16UC1 in mm (0 = invalid) or CV_32FC1 in m "
                         "(0 or NaN = invalid).")
      .output<DepthImage>("depth", "Filtered depth, same type, size and header as the input.")
      .param("size", 3, "Side length of the square window.",
             {.unit = "px",
              .choices = {std::int64_t{3}, std::int64_t{5}},
              .origin = "3 removes single-pixel speckle of structured-light sensors while "
                        "keeping object edges sharp; 5 also smooths quantisation steps"})
      .param("fill_holes", false,
             "Give an invalid pixel the median of its window when more than half of the "
             "window is valid (closes pinholes; off keeps every hole as measured).",
             {.origin = "off: later stages should see only measured depth"})
      .concurrency(Concurrency::clonable);
}

MedianFilter::MedianFilter(const Params& params)
    : median_(static_cast<int>(params.get_int("size")), params.get_bool("fill_holes")) {}

void MedianFilter::process(ProcessContext& ctx) {
  const auto& input = ctx.input<DepthImage>("depth");
  if (input.depth.empty()) throw StageError("input depth image is empty");
  DepthImage output;
  static_cast<FrameHeader&>(output) = input;
  try {
    output.depth = median_.apply(input.depth);
  } catch (const std::invalid_argument& error) {
    throw StageError(error.what());
  }
  ctx.output("depth", std::move(output));
}

}  // namespace facet::filters
