#include "ros2/stage_settings.hpp"

#include <chrono>
#include <cstdlib>
#include <stdexcept>

#include "facet/error.hpp"
#include "ros2/ros_names.hpp"

namespace facet::ros2 {

const Param<std::string> kTopic{"topic", "/camera/depth/image_rect_raw",
                                "ROS 2 topic of the depth images."};
const Param<std::string> kCameraInfo{
    "camera_info",
    "",
    "ROS 2 topic of the camera info; empty = 'camera_info' in the namespace of topic.",
    {.origin = "ROS camera convention"}};
const Param<std::int64_t> kDomain{
    "domain",
    -1,
    "DDS domain (ROS_DOMAIN_ID); -1 = the environment's ROS_DOMAIN_ID, else 0.",
    {.min = -1, .max = 232}};

std::string checked_dds_name(const std::string& ros_name, const std::string& param) {
  try {
    return dds_topic_name(ros_name);
  } catch (const std::invalid_argument& error) {
    throw StageError("param '" + param + "': " + error.what());
  }
}

std::uint32_t checked_domain(std::int64_t param) {
  try {
    return resolve_domain(param, std::getenv("ROS_DOMAIN_ID"));
  } catch (const std::invalid_argument& error) {
    throw StageError("param 'domain' is -1, but " + std::string(error.what()));
  }
}

std::int64_t system_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace facet::ros2
