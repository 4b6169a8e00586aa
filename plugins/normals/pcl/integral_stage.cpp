#include "normals/pcl/integral_stage.hpp"

#include <pcl/features/integral_image_normal.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <limits>
#include <string>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace facet::normals {

using Estimator = pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal>;

struct IntegralStage::Pcl {
  Estimator estimator;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
  pcl::PointCloud<pcl::Normal> normals;
};

namespace {

const In<DepthImage> kDepth{"depth",
                            "Depth image with intrinsics, CV_16UC1 in mm (0 = invalid) or "
                            "CV_32FC1 in m (0 or NaN = invalid)."};
const Out<NormalImage> kNormals{"normals",
                                "CV_32FC3 metric unit normals in the camera frame, same size and "
                                "header as the input, flipped towards the camera (PCL's viewpoint "
                                "0,0,0); NaN = no normal."};
const EnumParam<Estimator::NormalEstimationMethod> kMethod{
    "method",
    Estimator::AVERAGE_3D_GRADIENT,
    {{Estimator::COVARIANCE_MATRIX, "covariance"},
     {Estimator::AVERAGE_3D_GRADIENT, "average_3d_gradient"},
     {Estimator::AVERAGE_DEPTH_CHANGE, "average_depth_change"}},
    "PCL's estimation method. covariance: smallest eigenvector of the window's covariance; "
    "average_3d_gradient: cross product of the window's averaged horizontal and vertical 3D "
    "gradients; average_depth_change: from averaged depth changes only.",
    {.origin = "PCL 1.13 default (AVERAGE_3D_GRADIENT)"}};
const Param<double> kMaxDepthChangeFactor{
    "max_depth_change_factor",
    0.02,
    "Depth change between neighbours that PCL treats as a discontinuity, as a factor: a jump "
    "larger than 2 * factor * (depth_m + 1) ends the smoothing window.",
    {.unit = "m", .min = 0.0001, .max = 10.0, .origin = "PCL 1.13 default (20 * 0.001)"}};
const Param<double> kNormalSmoothingSize{
    "normal_smoothing_size",
    10.0,
    "Size of the area PCL averages over (its half-width in pixels, scaled with depth when "
    "depth_dependent_smoothing is on).",
    {.unit = "px", .min = 1.0, .max = 100.0, .origin = "PCL 1.13 default"}};
const Param<bool> kDepthDependentSmoothing{
    "depth_dependent_smoothing",
    false,
    "Scale the smoothing area with depth (PCL's setDepthDependentSmoothing).",
    {.origin = "PCL 1.13 default"}};

template <class DepthT>
void fill_cloud(const cv::Mat& depth, const CameraIntrinsics& camera, float to_m,
                pcl::PointCloud<pcl::PointXYZ>& cloud) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  const auto inv_fx = static_cast<float>(1.0 / camera.fx);
  const auto inv_fy = static_cast<float>(1.0 / camera.fy);
  for (int v = 0; v < depth.rows; ++v) {
    const auto* row = depth.ptr<DepthT>(v);
    const auto y_per_z = (static_cast<float>(v) - static_cast<float>(camera.cy)) * inv_fy;
    for (int u = 0; u < depth.cols; ++u) {
      const float z = static_cast<float>(row[u]) * to_m;
      auto& point = cloud(static_cast<std::size_t>(u), static_cast<std::size_t>(v));
      if (z > 0.0F) {  // also false for NaN
        point.x = (static_cast<float>(u) - static_cast<float>(camera.cx)) * inv_fx * z;
        point.y = y_per_z * z;
        point.z = z;
      } else {
        point.x = point.y = point.z = kNaN;
      }
    }
  }
}

}  // namespace

StageSpec IntegralStage::spec() {
  StageSpec spec("normals.integral",
                 "PCL's integral-image normal estimation (pcl::IntegralImageNormalEstimation).\n"
                 "The method robotics users know from PCL, for comparison with normals.cross and "
                 "normals.pca: the depth image is back-projected into an organized "
                 "pcl::PointCloud<PointXYZ> and PCL estimates metric 3D normals, smoothing over a "
                 "window that shrinks near depth discontinuities. Parameter defaults are PCL "
                 "1.13's.");
  return spec
      .declare(kDepth, kNormals, kMethod, kMaxDepthChangeFactor, kNormalSmoothingSize,
               kDepthDependentSmoothing)
      .concurrency(Concurrency::clonable);
}

IntegralStage::IntegralStage(const Params& params) : pcl_(std::make_unique<Pcl>()) {
  Estimator& estimator = pcl_->estimator;
  estimator.setNormalEstimationMethod(kMethod(params));
  estimator.setMaxDepthChangeFactor(static_cast<float>(kMaxDepthChangeFactor(params)));
  estimator.setNormalSmoothingSize(static_cast<float>(kNormalSmoothingSize(params)));
  estimator.setDepthDependentSmoothing(kDepthDependentSmoothing(params));
}

IntegralStage::~IntegralStage() = default;

void IntegralStage::process(ProcessContext& ctx) {
  const DepthImage& input = kDepth(ctx);
  if (!(input.camera.fx > 0.0 && input.camera.fy > 0.0)) {
    throw StageError("the depth image carries no camera intrinsics (fx, fy)");
  }
  auto& cloud = *pcl_->cloud;
  const auto width = static_cast<std::uint32_t>(input.depth.cols);
  const auto height = static_cast<std::uint32_t>(input.depth.rows);
  if (cloud.width != width || cloud.height != height) {
    cloud.resize(width, height);  // organized: width x height points
  }
  cloud.is_dense = false;
  if (input.depth.type() == CV_16UC1) {
    fill_cloud<std::uint16_t>(input.depth, input.camera, 0.001F, cloud);
  } else if (input.depth.type() == CV_32FC1) {
    fill_cloud<float>(input.depth, input.camera, 1.0F, cloud);
  } else {
    throw StageError("depth must be CV_16UC1 (mm) or CV_32FC1 (m)");
  }

  Estimator& estimator = pcl_->estimator;
  estimator.setInputCloud(pcl_->cloud);
  estimator.compute(pcl_->normals);

  cv::Mat normals(input.depth.rows, input.depth.cols, CV_32FC3);
  for (int v = 0; v < input.depth.rows; ++v) {
    auto* out = normals.ptr<float>(v);
    for (int u = 0; u < input.depth.cols; ++u) {
      const auto& normal = pcl_->normals(static_cast<std::size_t>(u), static_cast<std::size_t>(v));
      out[3 * u + 0] = normal.normal_x;
      out[3 * u + 1] = normal.normal_y;
      out[3 * u + 2] = normal.normal_z;
    }
  }
  kNormals(ctx, NormalImage::make(input, std::move(normals)));
}

}  // namespace facet::normals
