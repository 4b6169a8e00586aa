#pragma once
// ROS 2's naming and time conventions on DDS, as rmw_cyclonedds applies them: which DDS topic a
// ROS topic is, which domain a participant joins, and how a header stamp maps to nanoseconds.

#include <cstdint>
#include <optional>
#include <string>

namespace facet::ros2 {

// "/camera/depth/image_rect_raw" -> "rt/camera/depth/image_rect_raw" (ROS topics live under the
// "rt/" prefix on DDS; a relative name is resolved in the root namespace, as for a node without
// a namespace). Throws std::invalid_argument saying what is wrong with a name ROS 2 would refuse:
// empty, a trailing or doubled '/', characters other than letters, digits, '_' and '/', or a
// token starting with a digit.
std::string dds_topic_name(const std::string& ros_topic);

// The camera_info topic next to an image topic: its namespace plus "camera_info"
// ("/camera/depth/image_rect_raw" -> "/camera/depth/camera_info").
std::string default_camera_info_topic(const std::string& image_topic);

// The DDS domain: `param` when it is 0 or more, else ROS_DOMAIN_ID (`environment`, may be null),
// else 0. Throws std::invalid_argument for a ROS_DOMAIN_ID that is not a number in [0, 232].
std::uint32_t resolve_domain(std::int64_t param, const char* environment);

// builtin_interfaces/Time <-> nanoseconds since the epoch. Negative times round towards minus
// infinity, so that nanosec stays in [0, 1e9) as ROS 2 requires.
struct RosTime {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
};
RosTime to_ros_time(std::int64_t stamp_ns);
std::int64_t to_stamp_ns(RosTime time);

}  // namespace facet::ros2
