#pragma once
// From a point cloud (camera frame, metres) to the images of a depth frame: depth in mm,
// ground-truth labels, and the intrinsics that relate them. Nothing here depends on PCL.

#include <cstddef>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "facet/types/frame.hpp"

namespace facet::pcd {

// The points of one cloud, in the order stored. Organized clouds (height > 1) are row-major:
// point i is pixel (i % width, i / width). NaN, infinite or non-positive z = no measurement.
struct CloudPoints {
  int width = 0;
  int height = 0;
  std::vector<float> x, y, z;
  std::vector<std::uint32_t> labels;  // empty when the cloud has no label field

  std::size_t size() const { return z.size(); }
  bool organized() const { return height > 1; }
};

// A cloud stored with y and z negated (camera turned 180 degrees about x, as in some of PCL's
// tutorial clouds) has no point with z > 0 but points with z < 0. Negates y and z of such a
// cloud and returns true; leaves any other cloud alone and returns false.
bool flip_if_behind_camera(CloudPoints& cloud);

struct IntrinsicsFit {
  CameraIntrinsics camera;
  double rms_px = 0.0;     // root mean square of the u and v residuals
  std::size_t points = 0;  // valid points the fit used
};

// Least-squares fit of u = fx * x / z + cx and v = fy * y / z + cy over the valid points of an
// organized cloud, (u, v) being each point's column and row. Throws facet::StageError (with
// `what` in front) when the cloud does not determine them: fewer than two distinct columns or
// rows with valid points, or a non-positive focal length.
IntrinsicsFit fit_intrinsics(const CloudPoints& cloud, const std::string& what);

struct CloudImages {
  cv::Mat depth;   // CV_16UC1, mm, 0 = invalid
  cv::Mat labels;  // CV_32SC1 raw label values (0 where depth is invalid); empty without labels
  std::size_t out_of_range = 0;  // valid points beyond 65.535 m (left out)
  std::size_t outside = 0;       // re-projected points that fall outside the image (left out)
};

// Organized cloud: pixel (u, v) gets point v * width + u. Depth = round(z * 1000) mm.
CloudImages organized_images(const CloudPoints& cloud);

// Any cloud, projected with `camera` to pixel (round(fx * x / z + cx), round(fy * y / z + cy))
// of a camera.width x camera.height image; where several points land on one pixel the nearest
// wins (z-buffer).
CloudImages projected_images(const CloudPoints& cloud, const CameraIntrinsics& camera);

enum class LabelScheme { raw, mosd, mosd_parts };

// Turns raw label values into ground-truth ids (CV_32SC1, 0 = background); returns the largest
// id. raw: the values as stored. mosd: the mOSD scheme, where 0..9 are invalid and table and
// 10k..10k+9 are the parts of object k-1; every object gets one id 1..N in object order.
// mosd_parts: every value >= 20 gets its own id 1..M in value order.
std::int32_t apply_label_scheme(cv::Mat& labels, LabelScheme scheme);

}  // namespace facet::pcd
