#include "ros2/ros_names.hpp"

#include <cctype>
#include <charconv>
#include <stdexcept>

namespace facet::ros2 {
namespace {

constexpr std::int64_t kNsPerS = 1'000'000'000;
// ROS 2 refuses domain ids above 232: the DDS port numbers of larger ones leave the range.
constexpr std::int64_t kMaxDomain = 232;

bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '/';
}

}  // namespace

std::string dds_topic_name(const std::string& ros_topic) {
  const std::string quoted = "'" + ros_topic + "'";
  if (ros_topic.empty() || ros_topic == "/") {
    throw std::invalid_argument("topic name " + quoted + " is empty");
  }
  if (ros_topic.back() == '/') {
    throw std::invalid_argument("topic name " + quoted + " ends with '/'");
  }
  if (ros_topic.find("//") != std::string::npos) {
    throw std::invalid_argument("topic name " + quoted + " has an empty token ('//')");
  }
  for (std::size_t i = 0; i < ros_topic.size(); ++i) {
    const char c = ros_topic[i];
    if (!name_char(c)) {
      throw std::invalid_argument("topic name " + quoted + " has the character '" +
                                  std::string(1, c) +
                                  "' (only letters, digits, '_' and '/' are allowed)");
    }
    const bool token_start = i == 0 || ros_topic[i - 1] == '/';
    if (token_start && std::isdigit(static_cast<unsigned char>(c)) != 0) {
      throw std::invalid_argument("topic name " + quoted + " has a token starting with a digit");
    }
  }
  const std::string absolute = ros_topic.front() == '/' ? ros_topic.substr(1) : ros_topic;
  return "rt/" + absolute;
}

std::string default_camera_info_topic(const std::string& image_topic) {
  const auto slash = image_topic.rfind('/');
  if (slash == std::string::npos) return "camera_info";
  return image_topic.substr(0, slash + 1) + "camera_info";
}

std::uint32_t resolve_domain(std::int64_t param, const char* environment) {
  if (param >= 0) return static_cast<std::uint32_t>(param);
  if (environment == nullptr || *environment == '\0') return 0;
  const std::string text = environment;
  std::int64_t domain = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), domain);
  if (error != std::errc() || end != text.data() + text.size() || domain < 0 ||
      domain > kMaxDomain) {
    throw std::invalid_argument("ROS_DOMAIN_ID is '" + text + "', not a domain id from 0 to 232");
  }
  return static_cast<std::uint32_t>(domain);
}

RosTime to_ros_time(std::int64_t stamp_ns) {
  std::int64_t sec = stamp_ns / kNsPerS;
  std::int64_t nanosec = stamp_ns % kNsPerS;
  if (nanosec < 0) {
    nanosec += kNsPerS;
    sec -= 1;
  }
  return {static_cast<std::int32_t>(sec), static_cast<std::uint32_t>(nanosec)};
}

std::int64_t to_stamp_ns(RosTime time) {
  return static_cast<std::int64_t>(time.sec) * kNsPerS + static_cast<std::int64_t>(time.nanosec);
}

}  // namespace facet::ros2
