#pragma once
// sensor_msgs/Image and CameraInfo <-> facet's depth, label and camera types. Decoding checks
// everything a sender can get wrong and names the topic in its StageError; encoding builds
// messages that point into the caller's pixels (no copy: dds_write serializes at once).

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>

#include "facet/types/frame.hpp"
#include "sensor_msgs.h"

namespace facet::ros2 {

// Depth of a sensor_msgs/Image: "16UC1" (mm) as CV_16UC1, "32FC1" (m) as CV_32FC1, in host
// byte order, copied out of the message. Throws StageError naming `topic` for any other
// encoding, a step shorter than a row, or data whose size is not step * height.
cv::Mat decode_depth(const sensor_msgs_msg_dds__Image_& message, const std::string& topic);

// CV_32FC1 metres -> CV_16UC1 millimetres, rounded; NaN, infinite, <= 0 and beyond 65.535 m
// become 0 (no measurement).
cv::Mat metres_to_millimetres(const cv::Mat& depth_m);

// Pinhole intrinsics from K (fx = K[0], cx = K[2], fy = K[4], cy = K[5]) and the info's size.
// Throws StageError naming `topic` when fx or fy is not positive (ROS: K[0] == 0 means an
// uncalibrated camera) or the size is 0.
CameraIntrinsics decode_camera_info(const sensor_msgs_msg_dds__CameraInfo_& message,
                                    const std::string& topic);

// The header of a message. The strings are owned here; the C message points into them.
class HeaderFields {
 public:
  HeaderFields(std::int64_t stamp_ns, std::string frame_id);
  void fill(std_msgs_msg_dds__Header_& header);

 private:
  std::int64_t stamp_ns_;
  std::string frame_id_;
};

// A sensor_msgs/Image of single-channel pixels (CV_16UC1 as "16UC1", CV_32FC1 as "32FC1"),
// little endian, step = width * pixel size. Keeps `pixels` (made continuous) alive.
class ImageMessage {
 public:
  ImageMessage(const cv::Mat& pixels, std::int64_t stamp_ns, std::string frame_id);
  ImageMessage(const ImageMessage&) = delete;
  ImageMessage& operator=(const ImageMessage&) = delete;
  const sensor_msgs_msg_dds__Image_& message() const { return message_; }

 private:
  HeaderFields header_;
  cv::Mat pixels_;
  std::string encoding_;
  sensor_msgs_msg_dds__Image_ message_{};
};

// A sensor_msgs/CameraInfo of a rectified pinhole camera: distortion "plumb_bob" with zero
// coefficients, R the identity, P = [K | 0], no binning, no region of interest.
class CameraInfoMessage {
 public:
  CameraInfoMessage(const CameraIntrinsics& camera, std::int64_t stamp_ns, std::string frame_id);
  CameraInfoMessage(const CameraInfoMessage&) = delete;
  CameraInfoMessage& operator=(const CameraInfoMessage&) = delete;
  const sensor_msgs_msg_dds__CameraInfo_& message() const { return message_; }

 private:
  HeaderFields header_;
  std::string distortion_model_ = "plumb_bob";
  double distortion_[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  sensor_msgs_msg_dds__CameraInfo_ message_{};
};

// Segment ids as a 16-bit image for a "16UC1" labels topic. Throws StageError for ids outside
// [0, 65535].
cv::Mat labels_to_16u(const cv::Mat& labels);

}  // namespace facet::ros2
