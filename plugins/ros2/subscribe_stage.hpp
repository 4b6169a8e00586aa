#pragma once
// ros2.subscribe: depth frames from a ROS 2 camera over DDS (sensor_msgs/Image and the matching
// sensor_msgs/CameraInfo), without a ROS 2 installation.

#include <chrono>
#include <cstdint>
#include <string>

#include "facet/stage.hpp"
#include "ros2/dds_entities.hpp"
#include "ros2/stamp_matcher.hpp"

namespace facet::ros2 {

class SubscribeStage final : public Stage {
 public:
  static StageSpec spec();
  explicit SubscribeStage(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;
  void close() override;

 private:
  using Clock = std::chrono::steady_clock;

  // Takes what the readers hold into the matcher; returns whether anything came.
  bool take_available();
  std::optional<MatchedFrame> next_frame();

  // Parameters.
  std::string topic_;
  std::string camera_info_topic_;
  std::int64_t domain_param_;
  bool latest_;  // qos sensor: the newest frame; reliable: every frame in order
  QosProfile qos_;
  double idle_timeout_s_;
  bool output_mm_;

  // DDS, in deletion order (see dds_entities.hpp).
  DdsEntity participant_;
  DdsEntity image_topic_;
  DdsEntity info_topic_;
  DdsEntity image_reader_;
  DdsEntity info_reader_;
  DdsEntity waitset_;

  StampMatcher matcher_;
  std::int64_t delivered_ = 0;
  std::size_t unmatched_warned_ = 0;
  Clock::time_point last_message_;
};

}  // namespace facet::ros2
