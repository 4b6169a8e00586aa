#include "normals/cross_stage.hpp"

#include <string>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

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
      "normals disagree.");
  return spec
      .declare(kDepth, kNormals, kDepthSpaceParams, kRadius, kTriangle, kHoles, kSmoothRadius,
               kRenormalize)
      .concurrency(Concurrency::clonable);
}

CrossStage::CrossStage(const Params& params)
    : space_(kDepthSpaceParams(params)),
      options_{kRadius(params), kTriangle(params), kHoles(params)},
      smooth_radius_px_(kSmoothRadius(params)),
      smoother_(smooth_radius_px_, kRenormalize(params)) {}

void CrossStage::process(ProcessContext& ctx) {
  const DepthImage& input = kDepth(ctx);
  depth_to_z(input.depth, space_, z_);
  make_pixel_grid(space_, input.camera, z_.cols, z_.rows, grid_);

  cv::Mat normals;
  if (smooth_radius_px_ == 0) {
    cross_normals(z_, grid_, options_, normals, ctx.parallel_runner());
  } else {
    // Row by row: the unsmoothed normals never leave the cache as a whole image.
    smoother_.apply(
        z_.rows, z_.cols,
        [&](int y, float* row) { cross_normals_row(z_, grid_, options_, y, row); }, normals);
  }
  kNormals(ctx, NormalImage::make(input, std::move(normals)));
}

}  // namespace facet::normals
