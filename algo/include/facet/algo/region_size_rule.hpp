#pragma once
// The smallest region a stage keeps, by the area it covers rather than by a fixed pixel count.
// Shared by grow.surfaces (surface patches) and grow.blobs (object blobs).

#include <cstdint>

#include "facet/algo/pixel_scale.hpp"

namespace facet::algo {

// Up to reference_depth_m the smallest region is min_px; beyond, a region at depth z needs the
// area min_px covers at the reference depth, min_px * (reference_depth_m / z)^2 pixels, but
// never fewer than far_min_px. A surface seen from twice as far covers a quarter of the pixels,
// and its edge bands (a fixed number of pixels) eat a larger share of it, so a fixed pixel count
// drops far objects that near ones of the same size keep. The caller chooses the depth a region
// is judged at: grow.surfaces its mean depth, grow.blobs the depth of its first pixel.
struct RegionSizeRule {
  std::int64_t min_px = 100;
  double reference_depth_m = 0.0;  // 0: min_px at every depth
  std::int64_t far_min_px = 100;

  // The rule for a frame whose pixel counts scale by `scale` (an image of another resolution).
  RegionSizeRule scaled(const PixelScale& scale) const {
    return {scale.count(min_px), reference_depth_m, scale.count(far_min_px)};
  }

  bool depends_on_depth() const { return reference_depth_m > 0.0 && far_min_px < min_px; }
  // The fewest pixels any region can be kept with.
  std::int64_t smallest_px() const { return depends_on_depth() ? far_min_px : min_px; }

  // Whether a region of size_px pixels at depth depth_m is kept (NaN depth: min_px).
  bool keeps(std::int64_t size_px, double depth_m) const {
    if (size_px >= min_px) return true;
    if (!depends_on_depth() || size_px < far_min_px || !(depth_m > reference_depth_m)) {
      return false;
    }
    // size >= min_px * (reference / z)^2, without the division.
    const auto size = static_cast<double>(size_px);
    return size * depth_m * depth_m >=
           static_cast<double>(min_px) * reference_depth_m * reference_depth_m;
  }
};

}  // namespace facet::algo
