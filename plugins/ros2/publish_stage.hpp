#pragma once
// ros2.publish: depth (with its camera_info), labels and objects as ROS 2 topics over DDS.

#include <chrono>
#include <cstdint>
#include <string>

#include "facet/stage.hpp"
#include "facet/types/frame.hpp"
#include "facet/types/geometry.hpp"
#include "ros2/dds_entities.hpp"

namespace facet::ros2 {

class PublishStage final : public Stage {
 public:
  static StageSpec spec();
  explicit PublishStage(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;
  void close() override;

 private:
  using Clock = std::chrono::steady_clock;

  struct Publication {
    std::string ros_name;
    DdsEntity topic;
    DdsEntity writer;
  };

  Publication advertise(const dds_topic_descriptor_t& descriptor, const std::string& ros_name);
  void wait_for_readers(const Publication& publication) const;
  void pace();
  void flush(const Publication& publication) const;
  // The frame's own camera frame id, else the frame_id param.
  const std::string& header_frame_id(const FrameInfo& frame) const;
  void write(const Publication& publication, const void* message) const;
  void publish_objects(ProcessContext& ctx, const ObjectList& objects);

  // Parameters.
  std::string depth_topic_;
  std::string camera_info_topic_;
  std::string labels_topic_;
  std::string objects_topic_;
  std::string markers_topic_;
  std::int64_t domain_param_;
  QosProfile qos_;
  std::string frame_id_;  // for frames that carry no camera frame id
  bool stamp_now_;
  double rate_hz_;
  std::int64_t wait_for_readers_;
  double wait_timeout_s_;

  // DDS, in deletion order (see dds_entities.hpp); publications are advertised on first use.
  DdsEntity participant_;
  Publication depth_;
  Publication camera_info_;
  Publication labels_;
  Publication objects_;
  Publication markers_;

  Clock::time_point next_publish_{};
};

}  // namespace facet::ros2
