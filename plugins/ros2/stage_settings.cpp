#include "ros2/stage_settings.hpp"

#include <chrono>
#include <cstdlib>
#include <stdexcept>

#include "facet/error.hpp"
#include "ros2/ros_names.hpp"

namespace facet::ros2 {

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
