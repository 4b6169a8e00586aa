#pragma once
// What ros2.subscribe and ros2.publish read from their parameters and the environment in the
// same way: the parameters both declare alike, topic names and the domain checked into errors
// that name the parameter, and the clock their stamps and latencies are measured on.

#include <cstdint>
#include <string>

#include "facet/contract.hpp"

namespace facet::ros2 {

// The `topic`, `camera_info` and `domain` parameters, the same in both stages.
extern const Param<std::string> kTopic;
extern const Param<std::string> kCameraInfo;
extern const Param<std::int64_t> kDomain;

// The choices of the `qos` parameter (see QosProfile); each stage has its own default.
enum class Qos { sensor, reliable };

// The DDS name of `ros_name` (dds_topic_name); throws facet::StageError naming `param` and what
// ROS 2 would refuse in the name.
std::string checked_dds_name(const std::string& ros_name, const std::string& param);

// The domain a stage joins for its `domain` param (resolve_domain with ROS_DOMAIN_ID); throws
// facet::StageError when the param is -1 and ROS_DOMAIN_ID is not a domain.
std::uint32_t checked_domain(std::int64_t param);

// Nanoseconds since the epoch on the system clock, the clock of ROS 2 header stamps.
std::int64_t system_now_ns();

}  // namespace facet::ros2
