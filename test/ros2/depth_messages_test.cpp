// Decoding what a ROS 2 sender may get wrong, and encoding facet's images and intrinsics.

#include "ros2/depth_messages.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "facet/error.hpp"

namespace facet::ros2 {
namespace {

// A message over `bytes` (kept by the caller).
sensor_msgs_msg_dds__Image_ image_message(const char* encoding, std::uint32_t width,
                                          std::uint32_t height, std::uint32_t step,
                                          std::vector<std::uint8_t>& bytes) {
  sensor_msgs_msg_dds__Image_ message{};
  message.encoding = const_cast<char*>(encoding);
  message.width = width;
  message.height = height;
  message.step = step;
  message.data._buffer = bytes.data();
  message.data._length = static_cast<std::uint32_t>(bytes.size());
  message.data._maximum = message.data._length;
  return message;
}

std::string error_of(const sensor_msgs_msg_dds__Image_& message) {
  try {
    decode_depth(message, "/cam/depth");
  } catch (const StageError& error) {
    return error.what();
  }
  return "decoded";
}

TEST(DepthMessages, Decodes16UC1WithRowPaddingAndBigEndian) {
  // 2x2 pixels, rows padded to 6 bytes.
  std::vector<std::uint8_t> bytes = {0x01, 0x00, 0x02, 0x00, 0xEE, 0xEE,
                                     0x03, 0x00, 0x04, 0x01, 0xEE, 0xEE};
  auto message = image_message("16UC1", 2, 2, 6, bytes);
  const cv::Mat depth = decode_depth(message, "/cam/depth");
  ASSERT_EQ(depth.type(), CV_16UC1);
  EXPECT_EQ(depth.at<std::uint16_t>(0, 0), 1);
  EXPECT_EQ(depth.at<std::uint16_t>(0, 1), 2);
  EXPECT_EQ(depth.at<std::uint16_t>(1, 0), 3);
  EXPECT_EQ(depth.at<std::uint16_t>(1, 1), 0x0104);
  message.is_bigendian = 1;
  const cv::Mat swapped = decode_depth(message, "/cam/depth");
  EXPECT_EQ(swapped.at<std::uint16_t>(0, 0), 0x0100);
  EXPECT_EQ(swapped.at<std::uint16_t>(1, 1), 0x0401);
}

TEST(DepthMessages, Decodes32FC1Metres) {
  const float metres[2] = {0.5f, 1.25f};
  std::vector<std::uint8_t> bytes(sizeof(metres));
  std::memcpy(bytes.data(), metres, sizeof(metres));
  const auto message = image_message("32FC1", 2, 1, 8, bytes);
  const cv::Mat depth = decode_depth(message, "/cam/depth");
  ASSERT_EQ(depth.type(), CV_32FC1);
  EXPECT_EQ(depth.at<float>(0, 1), 1.25f);
}

TEST(DepthMessages, BadImagesAreErrorsNamingTheTopic) {
  std::vector<std::uint8_t> bytes(8, 0);
  const std::string encoding = error_of(image_message("rgb8", 2, 1, 6, bytes));
  EXPECT_NE(encoding.find("/cam/depth"), std::string::npos) << encoding;
  EXPECT_NE(encoding.find("'rgb8' is not depth"), std::string::npos) << encoding;
  EXPECT_EQ(error_of(image_message("16UC1", 2, 2, 4, bytes)), "decoded");
  const std::string short_data = error_of(image_message("16UC1", 2, 3, 4, bytes));
  EXPECT_NE(short_data.find("image data has 8 bytes, but step 4 x height 3 is 12"),
            std::string::npos)
      << short_data;
  const std::string step = error_of(image_message("16UC1", 4, 2, 4, bytes));
  EXPECT_NE(step.find("step 4 bytes is shorter than a row"), std::string::npos) << step;
  const std::string empty = error_of(image_message("16UC1", 0, 0, 0, bytes));
  EXPECT_NE(empty.find("empty image"), std::string::npos) << empty;
}

TEST(DepthMessages, MetresBecomeMillimetresAndInvalidBecomesZero) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  cv::Mat metres = (cv::Mat_<float>(1, 6) << 0.5004f, 1.0f, nan, inf, -1.0f, 70.0f);
  const cv::Mat mm = metres_to_millimetres(metres);
  ASSERT_EQ(mm.type(), CV_16UC1);
  const std::vector<std::uint16_t> expected = {500, 1000, 0, 0, 0, 0};
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(mm.at<std::uint16_t>(0, i), expected[static_cast<std::size_t>(i)]) << i;
}

TEST(DepthMessages, CameraInfoNeedsFocalLengths) {
  sensor_msgs_msg_dds__CameraInfo_ info{};
  info.width = 640;
  info.height = 480;
  try {
    decode_camera_info(info, "/cam/camera_info");
    ADD_FAILURE() << "a K of zeros was accepted";
  } catch (const StageError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("/cam/camera_info"), std::string::npos) << text;
    EXPECT_NE(text.find("uncalibrated"), std::string::npos) << text;
  }
  info.k[0] = 525.0;
  info.k[4] = 525.0;
  info.k[2] = 319.5;
  info.k[5] = 239.5;
  const CameraIntrinsics camera = decode_camera_info(info, "/cam/camera_info");
  EXPECT_EQ(camera, (CameraIntrinsics{525.0, 525.0, 319.5, 239.5, 640, 480}));
  info.width = 0;
  EXPECT_THROW(decode_camera_info(info, "/cam/camera_info"), StageError);
}

TEST(DepthMessages, EncodesWithoutCopyingAndWithTheHeader) {
  cv::Mat depth(2, 3, CV_16UC1, cv::Scalar(700));
  const ImageMessage image(depth, 1'500'000'000, "optical");
  const auto& message = image.message();
  EXPECT_EQ(message.header.stamp.sec, 1);
  EXPECT_EQ(message.header.stamp.nanosec, 500'000'000u);
  EXPECT_STREQ(message.header.frame_id, "optical");
  EXPECT_STREQ(message.encoding, "16UC1");
  EXPECT_EQ(message.step, 6u);
  EXPECT_EQ(message.data._length, 12u);
  EXPECT_EQ(message.data._buffer, depth.data);
  EXPECT_THROW(ImageMessage(cv::Mat(2, 2, CV_8UC3), 0, ""), StageError);
}

TEST(DepthMessages, LabelsOutside16BitsAreErrors) {
  cv::Mat labels = (cv::Mat_<std::int32_t>(1, 3) << 0, 3, 65535);
  EXPECT_EQ(labels_to_16u(labels).at<std::uint16_t>(0, 2), 65535);
  labels.at<std::int32_t>(0, 1) = 65536;
  EXPECT_THROW(labels_to_16u(labels), StageError);
  labels.at<std::int32_t>(0, 1) = -1;
  EXPECT_THROW(labels_to_16u(labels), StageError);
}

}  // namespace
}  // namespace facet::ros2
