#include "normals/cross_stage.hpp"

#include <string>

#include "facet/types/images.hpp"

namespace facet::normals {

StageSpec CrossStage::spec() {
  StageSpec spec(
      "normals.cross",
      "Surface normals from the cross product of two tangents spanned by neighbours at radius r.\n"
      "The paper's method (section II-A a): n = (B - A) x (C - A) for three pixels around p, "
      "normalised and oriented towards the camera. Computed in image space (the paper's: pixel "
      "grid augmented by depth, for edge detection) or metric space (true 3D normals). A pixel "
      "gets no normal (NaN) when it has no depth or a neighbour would lie outside the image, and "
      "when a neighbour used has no depth unless `holes` is one_sided. Optionally the normals are "
      "box-averaged afterwards; without "
      "renormalisation the averaged vectors are shorter where normals disagree.");
  spec.input<DepthImage>("depth",
                         "Depth image, CV_16UC1 in mm (0 = invalid) or CV_32FC1 in m (0 or NaN = "
                         "invalid); metric space needs its intrinsics.")
      .output<NormalImage>(
          "normals",
          "CV_32FC3 normals, same size and header as the input, oriented towards the camera, NaN "
          "= no normal. Unit length unless smoothing without renormalisation shortens them. In "
          "image space the components are in (px, px, scaled depth) space.");
  add_depth_space_params(spec);
  spec.param("radius", 2, "Distance r of the neighbours from the pixel.",
             {.unit = "px", .min = 1.0, .max = 16.0, .origin = "paper (r = 2)"})
      .param("triangle", "paper",
             "Neighbours spanning the tangents. paper: A = (x-r, y-r), B = (x+r, y-r), "
             "C = (x, y+r), n = (B - A) x (C - A) (not centred on the pixel); centred: "
             "((x+r, y) - (x-r, y)) x ((x, y+r) - (x, y-r)).",
             {.choices = {std::string("paper"), std::string("centred")},
              .origin = "paper (Fig. 2); the authors' later code uses the same triangle"})
      .param("holes", "none",
             "What a pixel with depth gets when a neighbour of its triangle has none. none: no "
             "normal (NaN). one_sided: the normal of the first one-sided tangent pair that avoids "
             "the hole, (p to (x+r, y) or (x-r, y)) x (p to (x, y+r) or (x, y-r)), tried "
             "right-below, left-below, right-above, left-above; NaN only when all four meet a "
             "hole. A one-pixel dropout line along an object's outline then stays one pixel wide "
             "instead of r pixels wider on each side.",
             {.choices = {std::string("none"), std::string("one_sided")},
              .origin = "paper (none); one_sided measured on the generated development sets "
                        "(docs/normals.md)"})
      .param("smooth_radius", 0,
             "Radius R of a box average of the normals over (2R+1)^2 pixels, over valid normals "
             "only (0 = off).",
             {.unit = "px",
              .min = 0.0,
              .max = 8.0,
              .origin = "paper (no smoothing of normals); the authors' later code offers R = 1"})
      .param("renormalize", false,
             "Scale averaged normals back to unit length. Off keeps the mean of unit vectors, "
             "shorter where the normals in the window disagree: dot products between neighbours "
             "then drop at creases, an implicit extra edge cue. Only used with smoothing.",
             {.origin = "authors' later code (averaged normals are not renormalised)"})
      .concurrency(Concurrency::clonable);
  return spec;
}

namespace {

Triangle triangle_from(const std::string& name) {
  if (name == "paper") return Triangle::paper;
  if (name == "centred") return Triangle::centred;
  throw StageError("unknown triangle '" + name + "' (paper, centred)");
}

HoleNormals hole_normals_from(const std::string& name) {
  if (name == "none") return HoleNormals::none;
  if (name == "one_sided") return HoleNormals::one_sided;
  throw StageError("unknown holes '" + name + "' (none, one_sided)");
}

}  // namespace

CrossStage::CrossStage(const Params& params)
    : space_(depth_space_from(params)),
      options_{static_cast<int>(params.get_int("radius")),
               triangle_from(params.get_string("triangle")),
               hole_normals_from(params.get_string("holes"))},
      smooth_radius_px_(static_cast<int>(params.get_int("smooth_radius"))),
      smoother_(smooth_radius_px_, params.get_bool("renormalize")) {}

void CrossStage::process(ProcessContext& ctx) {
  const auto& input = ctx.input<DepthImage>("depth");
  if (input.depth.empty()) throw StageError("input depth image is empty");
  depth_to_z(input.depth, space_, z_);
  make_pixel_grid(space_, input.camera, z_.cols, z_.rows, grid_);

  NormalImage output;
  static_cast<FrameHeader&>(output) = input;
  if (smooth_radius_px_ == 0) {
    cross_normals(z_, grid_, options_, output.normals, ctx.parallel_runner());
  } else {
    // Row by row: the unsmoothed normals never leave the cache as a whole image.
    smoother_.apply(
        z_.rows, z_.cols,
        [&](int y, float* row) { cross_normals_row(z_, grid_, options_, y, row); }, output.normals);
  }
  ctx.output("normals", std::move(output));
}

}  // namespace facet::normals
