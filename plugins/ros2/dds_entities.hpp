#pragma once
// Cyclone DDS entities owned RAII-style, and the two QoS profiles facet offers. Deleting a
// participant deletes its topics, readers and writers; the handles of those are then stale,
// so they are deleted before it (members in the order participant, topic, reader/writer).

#include <dds/dds.h>

#include <cstdint>
#include <string>

namespace facet::ros2 {

// "sensor": best effort, volatile (ROS 2's sensor-data profile); "reliable": reliable,
// volatile. Both keep the last `depth` samples.
struct QosProfile {
  bool reliable = false;
  std::int32_t depth = 1;
};

class DdsEntity {
 public:
  DdsEntity() = default;
  explicit DdsEntity(dds_entity_t handle) : handle_(handle) {}
  DdsEntity(DdsEntity&& other) noexcept : handle_(other.release()) {}
  DdsEntity& operator=(DdsEntity&& other) noexcept;
  DdsEntity(const DdsEntity&) = delete;
  DdsEntity& operator=(const DdsEntity&) = delete;
  ~DdsEntity() { reset(); }

  dds_entity_t get() const { return handle_; }
  explicit operator bool() const { return handle_ > 0; }
  void reset();
  dds_entity_t release();

 private:
  dds_entity_t handle_ = 0;
};

// Cyclone's text for a return code, e.g. "Timeout".
std::string dds_error_text(dds_return_t code);

// Each throws StageError naming `what` (the topic or the domain) when Cyclone refuses.
DdsEntity create_participant(std::uint32_t domain);
DdsEntity create_topic(const DdsEntity& participant, const dds_topic_descriptor_t& descriptor,
                       const std::string& dds_name, const std::string& ros_name);
DdsEntity create_reader(const DdsEntity& participant, const DdsEntity& topic, const QosProfile& qos,
                        const std::string& ros_name);
DdsEntity create_writer(const DdsEntity& participant, const DdsEntity& topic, const QosProfile& qos,
                        const std::string& ros_name);

// How many readers (for a writer) or writers (for a reader) are matched now.
std::uint32_t matched_count(const DdsEntity& endpoint, bool is_writer);

}  // namespace facet::ros2
