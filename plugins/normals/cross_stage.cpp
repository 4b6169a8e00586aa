#include "normals/cross_stage.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "normals/normal_noise.hpp"

namespace facet::normals {
namespace {

const In<DepthImage> kDepth{"depth",
                            "Depth image, CV_16UC1 in mm (0 = invalid) or CV_32FC1 in m (0 or NaN "
                            "= invalid); metric space needs its intrinsics."};
const Out<NormalImage> kNormals{
    "normals",
    "CV_32FC3 normals, same size and header as the input, oriented towards the camera, NaN = no "
    "normal. Unit length unless smoothing without renormalisation shortens them. In image space "
    "the components are in (px, px, scaled depth) space."};
const Param<int> kRadius{"radius",
                         2,
                         "Distance r of the neighbours from the pixel.",
                         {.unit = "px", .min = 1.0, .max = 16.0, .origin = "paper (r = 2)"}};
const EnumParam<Triangle> kTriangle{
    "triangle",
    Triangle::paper,
    {{Triangle::paper, "paper"}, {Triangle::centred, "centred"}},
    "Neighbours spanning the tangents. paper: A = (x-r, y-r), B = (x+r, y-r), C = (x, y+r), n = "
    "(B - A) x (C - A) (not centred on the pixel); centred: ((x+r, y) - (x-r, y)) x ((x, y+r) - "
    "(x, y-r)).",
    {.origin = "paper (Fig. 2); the authors' later code uses the same triangle"}};
const EnumParam<HoleNormals> kHoles{
    "holes",
    HoleNormals::none,
    {{HoleNormals::none, "none"}, {HoleNormals::one_sided, "one_sided"}},
    "What a pixel with depth gets when a neighbour of its triangle has none. none: no normal "
    "(NaN). one_sided: the normal of the first one-sided tangent pair that avoids the hole, (p to "
    "(x+r, y) or (x-r, y)) x (p to (x, y+r) or (x, y-r)), tried right-below, left-below, "
    "right-above, left-above; NaN only when all four meet a hole. A one-pixel dropout line along "
    "an object's outline then stays one pixel wide instead of r pixels wider on each side.",
    {.origin = "paper (none); one_sided measured on the generated development sets "
               "(docs/normals.md)"}};
const Param<int> kSmoothRadius{
    "smooth_radius",
    0,
    "Radius R of a box average of the normals over (2R+1)^2 pixels, over valid normals only (0 = "
    "off).",
    {.unit = "px",
     .min = 0.0,
     .max = 8.0,
     .origin = "paper (no smoothing of normals); the authors' later code offers R = 1"}};
const Param<int> kAutoSmoothMaxRadius{
    "auto_smooth_max_radius",
    0,
    "Automatic smoothing for sensors noisier than a Kinect. Noise and creases both make "
    "neighbouring normals (3 px apart, along rows and columns) differ by more than the edge "
    "filter's angle (auto_smooth_edge_threshold: 31.8 deg at 0.85); a box average removes the "
    "disagreement of noise and keeps that of creases. While averaging with one more radius "
    "would make at least auto_smooth_min_gain of the pairs agree, the radius grows, up to this "
    "one; the normals are then box-averaged and renormalised with it. Frames as noisy as the "
    "defaults were chosen on, and scenes full of creases, stay unsmoothed. Only with "
    "smooth_radius 0. 0 = off.",
    {.unit = "px",
     .min = 0.0,
     .max = 8.0,
     .origin = "measured on generated scenes with 1.5-3x the Kinect's noise: radius 3 smooths "
               "small objects away (docs/normals.md)"}};
const Param<double> kAutoSmoothMinGain{
    "auto_smooth_min_gain",
    0.125,
    "See auto_smooth_max_radius: the least share of the pixel pairs one more radius of "
    "averaging must make agree for the frame to be smoothed with it.",
    {.min = 0.0,
     .max = 1.0,
     .origin = "measured: radius 1 gains at most 0.112 on 272 generated frames with the "
               "Kinect's noise and 0.063 on the mOSD frames, 0.131 and more at 1.5x the noise, "
               "0.197 and more at 2x; 0.125 keeps every Kinect frame unsmoothed (0.11 smooths one) "
               "and smooths the noisier ones as 0.10 does (docs/normals.md)"}};
const Param<double> kAutoSmoothEdgeThreshold{
    "auto_smooth_edge_threshold",
    0.85,
    "See auto_smooth_max_radius: the edge filter's threshold (the cosine of its angle) the pairs "
    "of normals are measured against. Set it to the edges stage's threshold: a stricter edge "
    "filter (a larger threshold) takes smaller disagreements for creases, so it needs the "
    "normals smoothed at less noise.",
    {.min = 0.0,
     .max = 1.0,
     .origin = "edges.max's threshold in graphs/tabletop.yaml, which passes its graph parameter "
               "edge_threshold to both (docs/normals.md)"}};
const Param<bool> kRenormalize{
    "renormalize",
    false,
    "Scale averaged normals back to unit length. Off keeps the mean of unit vectors, shorter "
    "where the normals in the window disagree: dot products between neighbours then drop at "
    "creases, an implicit extra edge cue. Only used with smoothing.",
    {.origin = "authors' later code (averaged normals are not renormalised)"}};

}  // namespace

StageSpec CrossStage::spec() {
  StageSpec spec(
      "normals.cross",
      "Surface normals from the cross product of two tangents spanned by neighbours at radius r.\n"
      "The paper's method (section II-A a): n = (B - A) x (C - A) for three pixels around p, "
      "normalised and oriented towards the camera. Computed in image space (the paper's: pixel "
      "grid augmented by depth, for edge detection) or metric space (true 3D normals). A pixel "
      "gets no normal (NaN) when it has no depth or a neighbour would lie outside the image, and "
      "when a neighbour used has no depth unless `holes` is one_sided. Optionally the normals are "
      "box-averaged afterwards; without renormalisation the averaged vectors are shorter where "
      "normals disagree. With auto_smooth_max_radius, only a frame whose normals are too noisy "
      "for the edge filter is smoothed, as little as suffices.");
  return spec
      .declare(kDepth, kNormals, kDepthSpaceParams, kRadius, kTriangle, kHoles, kSmoothRadius,
               kRenormalize, kAutoSmoothMaxRadius, kAutoSmoothMinGain, kAutoSmoothEdgeThreshold)
      .concurrency(Concurrency::clonable);
}

CrossStage::CrossStage(const Params& params)
    : space_(kDepthSpaceParams(params)),
      options_{kRadius(params), kTriangle(params), kHoles(params)},
      smooth_radius_px_(kSmoothRadius(params)),
      smoother_(smooth_radius_px_, kRenormalize(params)),
      auto_max_radius_px_(kAutoSmoothMaxRadius(params)),
      auto_min_gain_(kAutoSmoothMinGain(params)),
      noisy_pairs_{.edge_threshold = kAutoSmoothEdgeThreshold(params)} {
  if (auto_max_radius_px_ > 0 && smooth_radius_px_ > 0) {
    throw StageError("smooth_radius " + std::to_string(smooth_radius_px_) +
                     " smooths every frame, auto_smooth_max_radius " +
                     std::to_string(auto_max_radius_px_) +
                     " only noisy ones: set one of them to 0");
  }
  for (int radius_px = 1; radius_px <= auto_max_radius_px_; ++radius_px)
    auto_smoothers_.emplace_back(radius_px, true);
  smoothed_.resize(auto_smoothers_.size());
}

void CrossStage::process(ProcessContext& ctx) {
  const DepthImage& input = kDepth(ctx);
  depth_to_z(input.depth, space_, z_);
  make_pixel_grid(space_, input.camera, z_.cols, z_.rows, grid_);

  cv::Mat normals;
  if (smooth_radius_px_ == 0) {
    cross_normals(z_, grid_, options_, normals, ctx.parallel_runner());
    if (auto_max_radius_px_ > 0) smooth_if_noisy(ctx, normals);
  } else {
    // Row by row: the unsmoothed normals never leave the cache as a whole image.
    smoother_.apply(
        z_.rows, z_.cols,
        [&](int y, float* row) { cross_normals_row(z_, grid_, options_, y, row); }, normals);
  }
  kNormals(ctx, NormalImage::make(input, std::move(normals)));
}

// The radius grows while one more makes at least auto_min_gain_ of the pairs agree. Each
// radius tried is the box average the frame would get (NormalSmoother, vectorised), measured at
// sampled pixels (noisy_pair_share); the one chosen is kept. Averaging cannot settle more pairs
// than disagree, so a share below the least gain ends the search without averaging: a frame that
// needs no smoothing costs one look at 1/16 of its normals.
void CrossStage::smooth_if_noisy(ProcessContext& ctx, cv::Mat& normals) {
  const double raw_share = noisy_pair_share(normals, noisy_pairs_);
  double share = raw_share;
  int radius_px = 0;
  while (radius_px < auto_max_radius_px_ && share >= auto_min_gain_) {
    const auto next = static_cast<std::size_t>(radius_px);
    auto_smoothers_[next].apply(normals, smoothed_[next]);
    const double next_share = noisy_pair_share(smoothed_[next], noisy_pairs_);
    if (share - next_share < auto_min_gain_) break;
    ++radius_px;
    share = next_share;
  }
  if (radius_px > 0) std::swap(normals, smoothed_[static_cast<std::size_t>(radius_px - 1)]);
  if (radius_px == auto_max_radius_px_ && share >= auto_min_gain_)
    warn_if_still_noisy(ctx, normals);
  ctx.metric("noisy_pair_share", raw_share);
  ctx.metric("smooth_radius_px", radius_px);
}

// Would averaging the result once more (radius 1) still settle auto_min_gain_ of the pairs? Only
// a warning depends on it, so the shares are looked at on every 8th row and column. The average
// goes to the scratch of radius 1: at the largest radius it holds no image still needed.
void CrossStage::warn_if_still_noisy(ProcessContext& ctx, const cv::Mat& smoothed) {
  NoisyPairRule coarse = noisy_pairs_;
  coarse.stride_px *= 2;
  cv::Mat& again = smoothed_.front();
  auto_smoothers_.front().apply(smoothed, again);
  const double share = noisy_pair_share(smoothed, coarse);
  const double gain = share - noisy_pair_share(again, coarse);
  if (gain < auto_min_gain_) return;
  ctx.warn("normals stay noisy after smoothing with radius " + std::to_string(auto_max_radius_px_) +
           " (auto_smooth_max_radius): " + std::to_string(std::lround(100.0 * share)) +
           " % of neighbouring normals differ by more than the edge angle, and more smoothing "
           "would settle " +
           std::to_string(std::lround(100.0 * gain)) + " % of them; expect few surface patches");
}

}  // namespace facet::normals
