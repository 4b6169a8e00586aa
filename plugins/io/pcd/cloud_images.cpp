#include "pcd/cloud_images.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "facet/error.hpp"

namespace facet::pcd {
namespace {

bool valid_point(const CloudPoints& cloud, std::size_t i) {
  return std::isfinite(cloud.x[i]) && std::isfinite(cloud.y[i]) && std::isfinite(cloud.z[i]) &&
         cloud.z[i] > 0.0F;
}

// Depth in mm, or 0 when it does not fit 16 bits.
std::uint16_t depth_mm(float z) {
  const double mm = std::round(static_cast<double>(z) * 1000.0);
  return mm >= 1.0 && mm <= 65535.0 ? static_cast<std::uint16_t>(mm) : 0;
}

// One axis of the fit: pixel = f * ratio + c, least squares, centred sums.
struct AxisFit {
  double f = 0.0;
  double c = 0.0;
  double sum_sq_residual = 0.0;
};

AxisFit fit_axis(const std::vector<double>& ratio, const std::vector<double>& pixel) {
  const double n = static_cast<double>(ratio.size());
  double mean_r = 0.0;
  double mean_p = 0.0;
  for (std::size_t i = 0; i < ratio.size(); ++i) {
    mean_r += ratio[i];
    mean_p += pixel[i];
  }
  mean_r /= n;
  mean_p /= n;
  double srr = 0.0;
  double srp = 0.0;
  for (std::size_t i = 0; i < ratio.size(); ++i) {
    srr += (ratio[i] - mean_r) * (ratio[i] - mean_r);
    srp += (ratio[i] - mean_r) * (pixel[i] - mean_p);
  }
  AxisFit fit;
  if (!(srr > 0.0)) return fit;
  fit.f = srp / srr;
  fit.c = mean_p - fit.f * mean_r;
  for (std::size_t i = 0; i < ratio.size(); ++i) {
    const double r = pixel[i] - (fit.f * ratio[i] + fit.c);
    fit.sum_sq_residual += r * r;
  }
  return fit;
}

}  // namespace

bool flip_if_behind_camera(CloudPoints& cloud) {
  bool in_front = false;
  bool behind = false;
  for (const float z : cloud.z) {
    if (!std::isfinite(z)) continue;
    in_front = in_front || z > 0.0F;
    behind = behind || z < 0.0F;
  }
  if (in_front || !behind) return false;
  for (float& y : cloud.y)
    y = -y;
  for (float& z : cloud.z)
    z = -z;
  return true;
}

IntrinsicsFit fit_intrinsics(const CloudPoints& cloud, const std::string& what) {
  if (!cloud.organized()) {
    throw StageError(what + ": intrinsics can only be fitted from an organized cloud");
  }
  std::vector<double> ratio_x, ratio_y, u, v;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!valid_point(cloud, i)) continue;
    ratio_x.push_back(static_cast<double>(cloud.x[i]) / cloud.z[i]);
    ratio_y.push_back(static_cast<double>(cloud.y[i]) / cloud.z[i]);
    u.push_back(static_cast<double>(i % static_cast<std::size_t>(cloud.width)));
    v.push_back(static_cast<double>(i / static_cast<std::size_t>(cloud.width)));
  }
  const std::string advice = "; give the intrinsics (params fx, fy, cx, cy or intrinsics)";
  if (ratio_x.size() < 2) {
    throw StageError(what + ": cannot fit intrinsics from " + std::to_string(ratio_x.size()) +
                     " valid points" + advice);
  }
  const AxisFit fit_u = fit_axis(ratio_x, u);
  const AxisFit fit_v = fit_axis(ratio_y, v);
  if (!(fit_u.f > 0.0) || !(fit_v.f > 0.0)) {
    throw StageError(what +
                     ": cannot fit intrinsics (the valid points span one row or column, or "
                     "do not project with a positive focal length)" +
                     advice);
  }
  IntrinsicsFit result;
  result.camera.fx = fit_u.f;
  result.camera.cx = fit_u.c;
  result.camera.fy = fit_v.f;
  result.camera.cy = fit_v.c;
  result.camera.width = cloud.width;
  result.camera.height = cloud.height;
  result.points = ratio_x.size();
  result.rms_px = std::sqrt((fit_u.sum_sq_residual + fit_v.sum_sq_residual) /
                            (2.0 * static_cast<double>(result.points)));
  return result;
}

CloudImages organized_images(const CloudPoints& cloud) {
  CloudImages images;
  images.depth = cv::Mat(cloud.height, cloud.width, CV_16UC1, cv::Scalar(0));
  const bool with_labels = !cloud.labels.empty();
  if (with_labels) images.labels = cv::Mat(cloud.height, cloud.width, CV_32SC1, cv::Scalar(0));
  auto* depth = images.depth.ptr<std::uint16_t>();
  auto* labels = with_labels ? images.labels.ptr<std::int32_t>() : nullptr;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!valid_point(cloud, i)) continue;
    depth[i] = depth_mm(cloud.z[i]);
    if (depth[i] == 0) {
      ++images.out_of_range;
      continue;
    }
    if (with_labels) labels[i] = static_cast<std::int32_t>(cloud.labels[i]);
  }
  return images;
}

CloudImages projected_images(const CloudPoints& cloud, const CameraIntrinsics& camera) {
  CloudImages images;
  images.depth = cv::Mat(camera.height, camera.width, CV_16UC1, cv::Scalar(0));
  const bool with_labels = !cloud.labels.empty();
  if (with_labels) images.labels = cv::Mat(camera.height, camera.width, CV_32SC1, cv::Scalar(0));
  // The nearest z per pixel (the z-buffer), before rounding to mm, so that ties in mm still go
  // to the nearer point.
  cv::Mat nearest(camera.height, camera.width, CV_32FC1,
                  cv::Scalar(std::numeric_limits<float>::infinity()));
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!valid_point(cloud, i)) continue;
    const std::uint16_t mm = depth_mm(cloud.z[i]);
    if (mm == 0) {
      ++images.out_of_range;
      continue;
    }
    const double u = std::round(camera.fx * cloud.x[i] / cloud.z[i] + camera.cx);
    const double v = std::round(camera.fy * cloud.y[i] / cloud.z[i] + camera.cy);
    if (!(u >= 0.0 && v >= 0.0 && u < camera.width && v < camera.height)) {
      ++images.outside;
      continue;
    }
    const int col = static_cast<int>(u);
    const int row = static_cast<int>(v);
    float& z_best = nearest.at<float>(row, col);
    if (cloud.z[i] >= z_best) continue;
    z_best = cloud.z[i];
    images.depth.at<std::uint16_t>(row, col) = mm;
    if (with_labels) images.labels.at<std::int32_t>(row, col) = static_cast<int>(cloud.labels[i]);
  }
  return images;
}

std::int32_t apply_label_scheme(cv::Mat& labels, LabelScheme scheme) {
  CV_Assert(labels.type() == CV_32SC1 && labels.isContinuous());
  auto* values = labels.ptr<std::int32_t>();
  const std::size_t count = labels.total();
  if (scheme == LabelScheme::raw) {
    std::int32_t largest = 0;
    for (std::size_t i = 0; i < count; ++i)
      largest = std::max(largest, values[i]);
    return largest;
  }
  // Key of a value: its object (mosd) or the value itself (mosd_parts); ids follow key order.
  const auto key = [scheme](std::int32_t value) {
    return scheme == LabelScheme::mosd ? value / 10 : value;
  };
  std::map<std::int32_t, std::int32_t> ids;
  for (std::size_t i = 0; i < count; ++i) {
    if (values[i] >= 20) ids.emplace(key(values[i]), 0);
  }
  std::int32_t next = 0;
  for (auto& [k, id] : ids)
    id = ++next;
  for (std::size_t i = 0; i < count; ++i) {
    values[i] = values[i] >= 20 ? ids.at(key(values[i])) : 0;
  }
  return next;
}

}  // namespace facet::pcd
