#include "ros2/depth_messages.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <opencv2/core.hpp>

#include "facet/error.hpp"
#include "ros2/ros_names.hpp"

namespace facet::ros2 {
namespace {

constexpr double kMaxDepth_mm = 65535.0;  // the largest depth CV_16UC1 holds
constexpr double kMaxLabel = 65535.0;     // the largest id a 16UC1 labels image holds

std::string text(const char* c_string) {
  return c_string == nullptr ? std::string() : std::string(c_string);
}

void swap_bytes(cv::Mat& pixels) {
  const std::size_t size = pixels.elemSize();
  for (int row = 0; row < pixels.rows; ++row) {
    auto* bytes = pixels.ptr<std::uint8_t>(row);
    for (int col = 0; col < pixels.cols; ++col) {
      std::uint8_t* pixel = bytes + static_cast<std::size_t>(col) * size;
      for (std::size_t i = 0; i < size / 2; ++i)
        std::swap(pixel[i], pixel[size - 1 - i]);
    }
  }
}

}  // namespace

cv::Mat decode_depth(const sensor_msgs_msg_dds__Image_& message, const std::string& topic) {
  const std::string encoding = text(message.encoding);
  int type = 0;
  if (encoding == "16UC1") {
    type = CV_16UC1;
  } else if (encoding == "32FC1") {
    type = CV_32FC1;
  } else {
    throw StageError("topic '" + topic + "': image encoding '" + encoding +
                     "' is not depth (expected 16UC1 in mm or 32FC1 in m)");
  }
  const std::uint64_t width = message.width;
  const std::uint64_t height = message.height;
  const std::uint64_t pixel_bytes = CV_ELEM_SIZE(type);
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width == 0 || height == 0) {
    throw StageError("topic '" + topic + "': empty image (" + size + ")");
  }
  if (width > static_cast<std::uint64_t>(INT32_MAX) ||
      height > static_cast<std::uint64_t>(INT32_MAX)) {
    throw StageError("topic '" + topic + "': image size " + size + " is too large");
  }
  if (message.step < width * pixel_bytes) {
    throw StageError("topic '" + topic + "': step " + std::to_string(message.step) +
                     " bytes is shorter than a row of " + size + " " + encoding + " (" +
                     std::to_string(width * pixel_bytes) + " bytes)");
  }
  const std::uint64_t expected = static_cast<std::uint64_t>(message.step) * height;
  if (message.data._length != expected) {
    throw StageError("topic '" + topic + "': image data has " +
                     std::to_string(message.data._length) + " bytes, but step " +
                     std::to_string(message.step) + " x height " + std::to_string(height) + " is " +
                     std::to_string(expected));
  }
  cv::Mat depth(static_cast<int>(height), static_cast<int>(width), type);
  for (int row = 0; row < depth.rows; ++row) {
    std::memcpy(depth.ptr(row), message.data._buffer + static_cast<std::size_t>(row) * message.step,
                width * pixel_bytes);
  }
  const bool big_endian_host = std::endian::native == std::endian::big;
  if ((message.is_bigendian != 0) != big_endian_host) swap_bytes(depth);
  return depth;
}

cv::Mat metres_to_millimetres(const cv::Mat& depth_m) {
  cv::Mat depth_mm(depth_m.size(), CV_16UC1);
  for (int row = 0; row < depth_m.rows; ++row) {
    const auto* in = depth_m.ptr<float>(row);
    auto* out = depth_mm.ptr<std::uint16_t>(row);
    for (int col = 0; col < depth_m.cols; ++col) {
      const double mm = std::round(static_cast<double>(in[col]) * 1000.0);
      // NaN fails both comparisons.
      out[col] = mm > 0.0 && mm <= kMaxDepth_mm ? static_cast<std::uint16_t>(mm) : 0;
    }
  }
  return depth_mm;
}

CameraIntrinsics decode_camera_info(const sensor_msgs_msg_dds__CameraInfo_& message,
                                    const std::string& topic) {
  CameraIntrinsics camera;
  camera.fx = message.k[0];
  camera.cx = message.k[2];
  camera.fy = message.k[4];
  camera.cy = message.k[5];
  camera.width = static_cast<int>(std::min<std::uint32_t>(message.width, INT32_MAX));
  camera.height = static_cast<int>(std::min<std::uint32_t>(message.height, INT32_MAX));
  if (!(camera.fx > 0.0) || !(camera.fy > 0.0) || !std::isfinite(camera.fx) ||
      !std::isfinite(camera.fy)) {
    throw StageError("topic '" + topic + "': camera_info K has fx = " + std::to_string(camera.fx) +
                     ", fy = " + std::to_string(camera.fy) +
                     " (an uncalibrated camera); facet needs the focal lengths");
  }
  if (camera.width <= 0 || camera.height <= 0) {
    throw StageError("topic '" + topic + "': camera_info has the size " +
                     std::to_string(message.width) + "x" + std::to_string(message.height));
  }
  return camera;
}

HeaderFields::HeaderFields(std::int64_t stamp_ns, std::string frame_id)
    : stamp_ns_(stamp_ns), frame_id_(std::move(frame_id)) {}

void HeaderFields::fill(std_msgs_msg_dds__Header_& header) {
  const RosTime time = to_ros_time(stamp_ns_);
  header.stamp.sec = time.sec;
  header.stamp.nanosec = time.nanosec;
  header.frame_id = frame_id_.data();
}

ImageMessage::ImageMessage(const cv::Mat& pixels, std::int64_t stamp_ns, std::string frame_id)
    : header_(stamp_ns, std::move(frame_id)),
      pixels_(pixels.isContinuous() ? pixels : pixels.clone()) {
  if (pixels_.type() == CV_16UC1) {
    encoding_ = "16UC1";
  } else if (pixels_.type() == CV_32FC1) {
    encoding_ = "32FC1";
  } else {
    throw StageError("cannot publish an image of OpenCV type " + std::to_string(pixels_.type()) +
                     " (expected CV_16UC1 or CV_32FC1)");
  }
  header_.fill(message_.header);
  message_.height = static_cast<std::uint32_t>(pixels_.rows);
  message_.width = static_cast<std::uint32_t>(pixels_.cols);
  message_.encoding = encoding_.data();
  message_.is_bigendian = std::endian::native == std::endian::big ? 1 : 0;
  message_.step = static_cast<std::uint32_t>(pixels_.cols * pixels_.elemSize());
  const auto bytes = static_cast<std::uint32_t>(pixels_.total() * pixels_.elemSize());
  message_.data._maximum = bytes;
  message_.data._length = bytes;
  message_.data._buffer = pixels_.data;
  message_.data._release = false;  // the pixels belong to pixels_, never to Cyclone
}

CameraInfoMessage::CameraInfoMessage(const CameraIntrinsics& camera, std::int64_t stamp_ns,
                                     std::string frame_id)
    : header_(stamp_ns, std::move(frame_id)) {
  header_.fill(message_.header);
  message_.height = static_cast<std::uint32_t>(camera.height);
  message_.width = static_cast<std::uint32_t>(camera.width);
  message_.distortion_model = distortion_model_.data();
  message_.d._maximum = 5;
  message_.d._length = 5;
  message_.d._buffer = distortion_;
  message_.d._release = false;
  const double k[9] = {camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0};
  const double r[9] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  const double p[12] = {camera.fx, 0.0, camera.cx, 0.0, 0.0, camera.fy,
                        camera.cy, 0.0, 0.0,       0.0, 1.0, 0.0};
  std::memcpy(message_.k, k, sizeof(k));
  std::memcpy(message_.r, r, sizeof(r));
  std::memcpy(message_.p, p, sizeof(p));
}

cv::Mat labels_to_16u(const cv::Mat& labels) {
  if (labels.channels() != 1 ||
      (labels.depth() != CV_32S && labels.depth() != CV_16U && labels.depth() != CV_8U)) {
    throw StageError("labels must be single-channel CV_32S, CV_16U or CV_8U");
  }
  double min_label = 0.0;
  double max_label = 0.0;
  cv::minMaxLoc(labels, &min_label, &max_label);
  if (min_label < 0.0 || max_label > kMaxLabel) {
    throw StageError("label ids from " + std::to_string(static_cast<long long>(min_label)) +
                     " to " + std::to_string(static_cast<long long>(max_label)) +
                     " do not fit a 16UC1 image (0 to 65535)");
  }
  cv::Mat ids;
  labels.convertTo(ids, CV_16U);
  return ids;
}

}  // namespace facet::ros2
