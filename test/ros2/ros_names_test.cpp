// ROS 2 names, domains and stamps on DDS.

#include "ros2/ros_names.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace facet::ros2 {
namespace {

TEST(Ros2Names, TopicsLiveUnderRtOnDds) {
  EXPECT_EQ(dds_topic_name("/camera/depth/image_rect_raw"), "rt/camera/depth/image_rect_raw");
  EXPECT_EQ(dds_topic_name("facet/labels"), "rt/facet/labels");
}

TEST(Ros2Names, NamesRos2RefusesAreErrorsSayingWhy) {
  const auto message = [](const std::string& name) {
    try {
      dds_topic_name(name);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("").find("empty"), std::string::npos);
  EXPECT_NE(message("/camera/").find("ends with '/'"), std::string::npos);
  EXPECT_NE(message("/camera//depth").find("'//'"), std::string::npos);
  EXPECT_NE(message("/camera/depth image").find("character ' '"), std::string::npos);
  EXPECT_NE(message("/camera/2d").find("digit"), std::string::npos);
}

TEST(Ros2Names, CameraInfoIsInTheImageTopicsNamespace) {
  EXPECT_EQ(default_camera_info_topic("/camera/depth/image_rect_raw"), "/camera/depth/camera_info");
  EXPECT_EQ(default_camera_info_topic("/image"), "/camera_info");
  EXPECT_EQ(default_camera_info_topic("image"), "camera_info");
}

TEST(Ros2Names, DomainFromParamThenEnvironmentThenZero) {
  EXPECT_EQ(resolve_domain(7, "42"), 7u);
  EXPECT_EQ(resolve_domain(-1, "42"), 42u);
  EXPECT_EQ(resolve_domain(-1, nullptr), 0u);
  EXPECT_EQ(resolve_domain(-1, ""), 0u);
  EXPECT_THROW(resolve_domain(-1, "abc"), std::invalid_argument);
  EXPECT_THROW(resolve_domain(-1, "233"), std::invalid_argument);
  EXPECT_THROW(resolve_domain(-1, "4x"), std::invalid_argument);
}

TEST(Ros2Names, StampsRoundTripWithNanosecondsInRange) {
  const RosTime time = to_ros_time(1'700'000'000'123'456'789);
  EXPECT_EQ(time.sec, 1'700'000'000);
  EXPECT_EQ(time.nanosec, 123'456'789u);
  EXPECT_EQ(to_stamp_ns(time), 1'700'000'000'123'456'789);
  const RosTime before_epoch = to_ros_time(-1);
  EXPECT_EQ(before_epoch.sec, -1);
  EXPECT_EQ(before_epoch.nanosec, 999'999'999u);
  EXPECT_EQ(to_stamp_ns(before_epoch), -1);
}

}  // namespace
}  // namespace facet::ros2
