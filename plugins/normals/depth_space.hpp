#pragma once
// The space normals are computed in, and the conversion of a depth image into it.
//
// image  — the paper's: the pixel grid augmented by depth, points (u px, v px, z) with z the
//          depth in a scaled unit (see ImageDepth). Normals there are meant for edge detection
//          (angles between neighbouring normals), not for 3D directions.
// metric — true 3D normals of the back-projected points (metres, camera frame).

#include <opencv2/core/mat.hpp>
#include <string_view>
#include <vector>

#include "facet/contract.hpp"
#include "facet/stage_spec.hpp"
#include "facet/types/frame.hpp"

namespace facet::normals {

enum class Space { image, metric };

// The unit of z in image space.
//   disparity: the raw 11-bit Kinect v1 disparity computed from depth,
//              raw = (3.3309495161 - 1046 / depth_mm) / 0.0030711016,
//              times width / 320 (the authors worked at 320x240: one VGA pixel is half a QVGA
//              pixel, so disparity steps per pixel are doubled to keep their slopes).
//   mm:        depth in millimetres.
// Either is then multiplied by `depth_scale`.
enum class ImageDepth { disparity, mm };

struct DepthSpace {
  Space space = Space::image;
  ImageDepth image_depth = ImageDepth::disparity;
  double depth_scale = 1.0;
};

// The Kinect v1 relation between its raw disparity and depth in millimetres:
// depth_mm = 1046 / (3.3309495161 - 0.0030711016 raw).
inline constexpr double kKinectDisparityOffset = 3.3309495161;
inline constexpr double kKinectDisparityFactor = 0.0030711016;
inline constexpr double kKinectDisparityMm = 1046.0;
// The image width the authors' disparity slopes refer to (QVGA).
inline constexpr double kAuthorsWidthPx = 320.0;

inline double kinect_raw_disparity(double depth_mm) {
  return (kKinectDisparityOffset - kKinectDisparityMm / depth_mm) / kKinectDisparityFactor;
}

// The `space`, `image_depth` and `depth_scale` parameters every normals stage shares:
// `spec.declare(kDepthSpaceParams)` declares them, `kDepthSpaceParams(params)` reads them.
struct DepthSpaceParams {
  EnumParam<Space> space;
  EnumParam<ImageDepth> image_depth;
  Param<double> depth_scale;

  void declare_in(StageSpec& spec) const { spec.declare(space, image_depth, depth_scale); }
  DepthSpace operator()(const Params& params) const {
    return {space(params), image_depth(params), depth_scale(params)};
  }
};
extern const DepthSpaceParams kDepthSpaceParams;

// Third coordinate of every pixel in `space`, as CV_32FC1; NaN where the depth is invalid
// (0 or NaN in the input, or not positive). Metric: metres. Image: the scaled unit above.
// `z` is reused when it already has the right size and type.
void depth_to_z(const cv::Mat& depth, const DepthSpace& space, cv::Mat& z);

// The first two coordinates of a pixel in `space` are col_factor[u] * s and row_factor[v] * s,
// where s = z in metric space and s = 1 in image space (then the factors are u and v).
struct PixelGrid {
  std::vector<float> col_factor;
  std::vector<float> row_factor;
  bool scale_by_z = false;
};
// Throws StageError when metric space is asked for without valid intrinsics.
void make_pixel_grid(const DepthSpace& space, const CameraIntrinsics& camera, int width, int height,
                     PixelGrid& grid);

}  // namespace facet::normals
