#pragma once
// Parameters in pixels that stand for a size in the scene, scaled with the image's resolution.
//
// The defaults of the stages were chosen on 640 x 480 depth images. The same scene seen by the
// same camera at 320 x 240 covers a quarter of the pixels, so a region size of 100 px there
// asks for a surface four times as large; at 1280 x 960 it asks for a quarter of it. A stage
// therefore states such parameters for a reference image area and scales them per frame: pixel
// counts (areas) with the ratio of the areas, pixel lengths (widths, radii) with its square
// root. Parameters that stand for a property of the image rather than of the scene (the width of
// an edge band, a filter window, a sampling stride) are not scaled.
//
// Why the image area and not the focal length: a camera of longer focal length at the same
// resolution (YCB-Video's Xtion, fx 1067 px) sees the same surface in more pixels, but scaling
// the counts by fx^2 lost objects there (F 0.709 -> 0.621, docs/evaluation.md); its noise and
// edge bands are those of a 640 x 480 sensor. A crop of a larger image keeps its pixels' size but
// not its area: run it with reference_area_px 0, or set it to the area of the uncropped image.

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <opencv2/core/types.hpp>
#include <type_traits>

#include "facet/contract.hpp"

namespace facet::algo {

// The image area (width x height) the defaults were chosen at: a Kinect's 640 x 480.
inline constexpr std::int64_t kDefaultReferenceAreaPx = 640 * 480;

// The parameter every stage with scene-size pixel parameters declares, under one name and doc.
inline const Param<std::int64_t> kReferenceAreaParam{
    "reference_area_px",
    kDefaultReferenceAreaPx,
    "The image area (width x height) this stage's pixel counts and scene-size pixel lengths are "
    "given for. On a frame of W x H pixels the counts are multiplied by W*H / reference_area_px "
    "and the lengths by its square root, so that they ask for the same surface at any "
    "resolution (at 320 x 240 a quarter of the count, half the length). 0 = use them as given "
    "(a crop of a larger image: 0, or the uncropped image's area).",
    {.unit = "px",
     .min = 0.0,
     .max = 1.0e9,
     .origin = "640 x 480, where the defaults were chosen; generated scenes at 320 x 240: F "
               "0.789 unscaled, 0.843 scaled (docs/evaluation.md)"}};

// The factors of one frame. Identity at the reference area, so 640 x 480 frames see exactly the
// parameters as given.
class PixelScale {
 public:
  PixelScale() = default;
  // reference_area_px 0 (or an empty image): identity.
  PixelScale(std::int64_t reference_area_px, cv::Size image) {
    const std::int64_t image_area_px = static_cast<std::int64_t>(image.width) * image.height;
    if (reference_area_px > 0 && image_area_px > 0 && image_area_px != reference_area_px) {
      area_factor_ = static_cast<double>(image_area_px) / static_cast<double>(reference_area_px);
      length_factor_ = std::sqrt(area_factor_);
    }
  }

  double area_factor() const { return area_factor_; }
  double length_factor() const { return length_factor_; }

  // A pixel count, rounded, never below least_px; in the integer type the rule holds it in.
  template <std::integral Count>
  Count count(Count count_px, std::type_identity_t<Count> least_px = 1) const {
    if (area_factor_ == 1.0) return count_px;
    const auto scaled =
        static_cast<Count>(std::llround(static_cast<double>(count_px) * area_factor_));
    return std::max(least_px, scaled);
  }
  // A length in pixels (a width, a radius), unrounded.
  double length(double length_px) const { return length_px * length_factor_; }

 private:
  double area_factor_ = 1.0;
  double length_factor_ = 1.0;
};

}  // namespace facet::algo
