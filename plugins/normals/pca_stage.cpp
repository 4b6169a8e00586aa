#include "normals/pca_stage.hpp"

#include <cmath>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace facet::normals {

namespace {

const In<DepthImage> kDepth{"depth",
                            "Depth image, CV_16UC1 in mm (0 = invalid) or CV_32FC1 in m (0 or NaN "
                            "= invalid); metric space needs its intrinsics."};
const Out<NormalImage> kNormals{"normals",
                                "CV_32FC3 unit normals, same size and header as the input, "
                                "oriented towards the camera, NaN = no normal. In image space the "
                                "components are in (px, px, scaled depth) space."};
const Param<int> kWindow{
    "window",
    5,
    "Side length k of the square window (odd).",
    {.unit = "px",
     .min = 3.0,
     .max = 31.0,
     .origin = "paper Table I (3 and 5); 5 was the more stable of the two there"}};
const Param<double> kMinValidFraction{
    "min_valid_fraction",
    0.5,
    "Fraction of the window's k^2 points that must be valid (at least 3 points always).",
    {.min = 0.0,
     .max = 1.0,
     .origin = "not in the paper (nor in the authors' code, which has no PCA): a majority, so a "
               "hole's rim still gets normals from the measured side"}};

PcaOptions pca_options_from(const Params& params) {
  const int window = kWindow(params);
  if (window % 2 == 0) throw StageError("window must be odd, got " + std::to_string(window));
  const double fraction = kMinValidFraction(params);
  return {window, static_cast<int>(std::ceil(fraction * window * window))};
}

}  // namespace

StageSpec PcaStage::spec() {
  StageSpec spec(
      "normals.pca",
      "Surface normals by PCA of the valid points of a k x k window.\n"
      "The normal is the eigenvector of the smallest eigenvalue of the covariance of the window's "
      "valid points, oriented towards the camera; the paper compares it with the cross product "
      "(Table I: 3x3 and 5x5). Same spaces as normals.cross. A pixel gets no normal (NaN) when "
      "its own depth is invalid, its window leaves the image, or too few points of the window "
      "are valid; invalid points are left out, never filled in.");
  return spec.declare(kDepth, kNormals, kDepthSpaceParams, kWindow, kMinValidFraction)
      .concurrency(Concurrency::clonable);
}

PcaStage::PcaStage(const Params& params)
    : space_(kDepthSpaceParams(params)), pca_(pca_options_from(params)) {}

void PcaStage::process(ProcessContext& ctx) {
  const DepthImage& input = kDepth(ctx);
  depth_to_z(input.depth, space_, z_);
  make_pixel_grid(space_, input.camera, z_.cols, z_.rows, grid_);
  cv::Mat normals;
  pca_.apply(z_, grid_, normals);
  kNormals(ctx, NormalImage::make(input, std::move(normals)));
}

}  // namespace facet::normals
