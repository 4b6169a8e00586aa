#include "normals/depth_space.hpp"

#include <cstdint>
#include <limits>
#include <string>

#include "facet/error.hpp"

namespace facet::normals {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// z = scale * depth, NaN unless depth > 0 (NaN fails the comparison too).
template <class DepthT>
void linear_row(const DepthT* depth, float scale, float* z, int width) {
  for (int u = 0; u < width; ++u) {
    const auto d = static_cast<float>(depth[u]);
    z[u] = d > 0.0F ? d * scale : kNaN;
  }
}

// z = scale * raw disparity of depth * to_mm; an affine function of 1 / depth, so a division
// per pixel (vectorised) rather than a table lookup (which would not vectorise).
template <class DepthT>
void disparity_row(const DepthT* depth, float to_mm, float scale, float* z, int width) {
  const auto offset = static_cast<float>(kKinectDisparityOffset / kKinectDisparityFactor);
  const auto slope = static_cast<float>(kKinectDisparityMm / kKinectDisparityFactor);
  for (int u = 0; u < width; ++u) {
    const float mm = static_cast<float>(depth[u]) * to_mm;
    z[u] = mm > 0.0F ? scale * (offset - slope / mm) : kNaN;
  }
}

template <class DepthT>
void convert(const cv::Mat& depth, const DepthSpace& space, float to_m, cv::Mat& z) {
  const float to_mm = to_m * 1000.0F;
  for (int v = 0; v < depth.rows; ++v) {
    const auto* in = depth.ptr<DepthT>(v);
    auto* out = z.ptr<float>(v);
    if (space.space == Space::metric) {
      linear_row(in, to_m, out, depth.cols);
    } else if (space.image_depth == ImageDepth::mm) {
      linear_row(in, to_mm * static_cast<float>(space.depth_scale), out, depth.cols);
    } else {
      const double per_resolution = depth.cols / kAuthorsWidthPx;
      disparity_row(in, to_mm, static_cast<float>(space.depth_scale * per_resolution), out,
                    depth.cols);
    }
  }
}

}  // namespace

const DepthSpaceParams kDepthSpaceParams{
    EnumParam<Space>{
        "space",
        Space::image,
        {{Space::image, "image"}, {Space::metric, "metric"}},
        "Space the normals are computed in. image: the paper's, the pixel grid augmented by "
        "depth, points (u px, v px, scaled depth); its normals are for edge detection (angles "
        "between neighbouring normals), not 3D directions. metric: true 3D normals of the "
        "back-projected points (needs the intrinsics).",
        {.origin = "paper (normals on the depth image, not the point cloud); in the project's "
                   "prototype on the 45 mOSD learn frames, image space scored F 0.950 and metric "
                   "0.943, each at its best edge threshold"}},
    EnumParam<ImageDepth>{
        "image_depth",
        ImageDepth::disparity,
        {{ImageDepth::disparity, "disparity"}, {ImageDepth::mm, "mm"}},
        "Unit of depth in image space. disparity: the raw Kinect v1 disparity computed from "
        "depth, raw = (3.3309495161 - 1046 / depth_mm) / 0.0030711016, times width / 320 (keeps "
        "the slopes of the authors' 320x240 images); mm: millimetres. Ignored in metric space.",
        {.origin = "authors' later code (raw 11-bit disparity at 320x240, where the paper's edge "
                   "threshold 0.85 was tuned)"}},
    Param<double>{"depth_scale",
                  1.0,
                  "Factor on the image-space depth unit: larger makes surfaces look steeper and "
                  "normal edges stronger. Ignored in metric space.",
                  {.min = 0.01,
                   .max = 100.0,
                   .origin = "1: the unit as defined by image_depth, no extra scaling"}}};

void depth_to_z(const cv::Mat& depth, const DepthSpace& space, cv::Mat& z) {
  if (depth.type() != CV_16UC1 && depth.type() != CV_32FC1) {
    throw StageError("depth must be CV_16UC1 (mm) or CV_32FC1 (m)");
  }
  z.create(depth.rows, depth.cols, CV_32FC1);
  if (depth.type() == CV_16UC1) {
    convert<std::uint16_t>(depth, space, 0.001F, z);
  } else {
    convert<float>(depth, space, 1.0F, z);
  }
}

void make_pixel_grid(const DepthSpace& space, const CameraIntrinsics& camera, int width, int height,
                     PixelGrid& grid) {
  grid.col_factor.resize(static_cast<std::size_t>(width));
  grid.row_factor.resize(static_cast<std::size_t>(height));
  grid.scale_by_z = space.space == Space::metric;
  if (grid.scale_by_z && !(camera.fx > 0.0 && camera.fy > 0.0)) {
    throw StageError(
        "metric space needs the camera intrinsics (fx, fy), which the depth image "
        "does not carry");
  }
  for (int u = 0; u < width; ++u) {
    grid.col_factor[static_cast<std::size_t>(u)] =
        grid.scale_by_z ? static_cast<float>((u - camera.cx) / camera.fx) : static_cast<float>(u);
  }
  for (int v = 0; v < height; ++v) {
    grid.row_factor[static_cast<std::size_t>(v)] =
        grid.scale_by_z ? static_cast<float>((v - camera.cy) / camera.fy) : static_cast<float>(v);
  }
}

}  // namespace facet::normals
