#include "ros2/dds_entities.hpp"

#include <memory>
#include <utility>

#include "facet/error.hpp"

namespace facet::ros2 {
namespace {

struct QosDeleter {
  void operator()(dds_qos_t* qos) const { dds_delete_qos(qos); }
};
using QosPtr = std::unique_ptr<dds_qos_t, QosDeleter>;

QosPtr make_qos(const QosProfile& profile) {
  QosPtr qos(dds_create_qos());
  if (profile.reliable) {
    // A writer blocks at most this long when a reader's history is full (never here: both
    // sides keep the last N).
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  } else {
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_BEST_EFFORT, 0);
  }
  dds_qset_durability(qos.get(), DDS_DURABILITY_VOLATILE);
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, profile.depth);
  return qos;
}

}  // namespace

DdsEntity& DdsEntity::operator=(DdsEntity&& other) noexcept {
  if (this != &other) {
    reset();
    handle_ = other.release();
  }
  return *this;
}

void DdsEntity::reset() {
  if (handle_ > 0) dds_delete(handle_);
  handle_ = 0;
}

dds_entity_t DdsEntity::release() {
  return std::exchange(handle_, 0);
}

std::string dds_error_text(dds_return_t code) {
  const char* text = dds_strretcode(code);
  return text == nullptr ? "error " + std::to_string(code) : std::string(text);
}

DdsEntity create_participant(std::uint32_t domain) {
  const dds_entity_t participant = dds_create_participant(domain, nullptr, nullptr);
  if (participant < 0) {
    throw StageError("cannot join DDS domain " + std::to_string(domain) + ": " +
                     dds_error_text(participant) +
                     " (check CYCLONEDDS_URI and the network interfaces)");
  }
  return DdsEntity(participant);
}

DdsEntity create_topic(const DdsEntity& participant, const dds_topic_descriptor_t& descriptor,
                       const std::string& dds_name, const std::string& ros_name) {
  const dds_entity_t topic =
      dds_create_topic(participant.get(), &descriptor, dds_name.c_str(), nullptr, nullptr);
  if (topic < 0) {
    throw StageError("cannot create topic '" + ros_name + "' (DDS '" + dds_name + "', type " +
                     descriptor.m_typename + "): " + dds_error_text(topic));
  }
  return DdsEntity(topic);
}

DdsEntity create_reader(const DdsEntity& participant, const DdsEntity& topic, const QosProfile& qos,
                        const std::string& ros_name) {
  const auto settings = make_qos(qos);
  const dds_entity_t reader =
      dds_create_reader(participant.get(), topic.get(), settings.get(), nullptr);
  if (reader < 0) {
    throw StageError("cannot subscribe to '" + ros_name + "': " + dds_error_text(reader));
  }
  return DdsEntity(reader);
}

DdsEntity create_writer(const DdsEntity& participant, const DdsEntity& topic, const QosProfile& qos,
                        const std::string& ros_name) {
  const auto settings = make_qos(qos);
  const dds_entity_t writer =
      dds_create_writer(participant.get(), topic.get(), settings.get(), nullptr);
  if (writer < 0) {
    throw StageError("cannot publish on '" + ros_name + "': " + dds_error_text(writer));
  }
  return DdsEntity(writer);
}

std::uint32_t matched_count(const DdsEntity& endpoint, bool is_writer) {
  if (is_writer) {
    dds_publication_matched_status_t status{};
    if (dds_get_publication_matched_status(endpoint.get(), &status) < 0) return 0;
    return status.current_count;
  }
  dds_subscription_matched_status_t status{};
  if (dds_get_subscription_matched_status(endpoint.get(), &status) < 0) return 0;
  return status.current_count;
}

}  // namespace facet::ros2
