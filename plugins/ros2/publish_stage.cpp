#include "ros2/publish_stage.hpp"

#include <chrono>
#include <thread>

#include "facet/contract.hpp"
#include "facet/error.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "ros2/depth_messages.hpp"
#include "ros2/object_messages.hpp"
#include "ros2/ros_names.hpp"
#include "ros2/stage_settings.hpp"

namespace facet::ros2 {
namespace {

// How often the matched readers are looked at while waiting for them.
constexpr auto kMatchPoll = std::chrono::milliseconds(10);

// Which time a message's header stamp gives.
enum class Stamp { frame, now };

const OptionalIn<DepthImage> kDepth{"depth", "Depth, CV_16UC1 in mm or CV_32FC1 in m."};
const OptionalIn<LabelImage> kLabels{"labels", "Object ids, 0 = background, at most 65535."};
const OptionalIn<ObjectList> kObjects{"objects", "Object models (shape.superquadric's output)."};
const OptionalIn<SupportPlanes> kPlanes{"planes",
                                        "Support planes, for the coefficients of each object's "
                                        "support plane in the objects message."};
const Param<std::string> kLabelsTopic{"labels_topic", "/facet/labels",
                                      "ROS 2 topic of the label images."};
const Param<std::string> kObjectsTopic{"objects_topic", "/facet/objects",
                                       "ROS 2 topic of the facet_msgs/msg/Objects."};
const Param<std::string> kMarkersTopic{
    "markers_topic", "/facet/markers",
    "ROS 2 topic of the visualization_msgs/msg/MarkerArray for RViz."};
const EnumParam<Qos> kQos{
    "qos",
    Qos::reliable,
    {{Qos::sensor, "sensor"}, {Qos::reliable, "reliable"}},
    "reliable: reliable writers (matched by reliable and best-effort readers); sensor: "
    "best effort."};
const Param<int> kHistoryDepth{
    "history_depth", 10, "Samples each DDS writer keeps (keep last N).", {.min = 1, .max = 1000}};
const Param<std::string> kFrameId{
    "frame_id",
    "camera_depth_optical_frame",
    "Header frame_id for frames without a camera frame id of their own (read from "
    "files or OpenNI2); frames from ros2.subscribe keep the one they came with.",
    {.origin = "ROS REP 103/105: the optical frame of a depth camera"}};
const EnumParam<Stamp> kStamp{
    "stamp",
    Stamp::frame,
    {{Stamp::frame, "frame"}, {Stamp::now, "now"}},
    "frame: the frame's timestamp; now: the system clock when publishing (a recording "
    "played as a live camera)."};
const Param<double> kRate{"rate_hz",
                          0.0,
                          "Most messages per second per topic; 0 = as fast as frames come.",
                          {.unit = "Hz", .min = 0.0, .max = 1000.0}};
const Param<std::int64_t> kWaitForReaders{
    "wait_for_readers",
    0,
    "Readers each topic waits for before its first message; 0 = none.",
    {.min = 0, .max = 1000}};
const Param<double> kWaitTimeout{
    "wait_timeout_s",
    10.0,
    "How long to wait for those readers (an error naming the topic after that) and, "
    "at the end, for reliable readers to acknowledge.",
    {.unit = "s", .min = 0.0, .max = 3600.0}};

}  // namespace

StageSpec PublishStage::spec() {
  StageSpec spec(
      "ros2.publish",
      "Publishes depth (with its camera_info), labels and objects as ROS 2 topics over DDS "
      "(Cyclone DDS; see docs/ros2.md).\n"
      "depth goes out as sensor_msgs/msg/Image (16UC1 in mm, or 32FC1 in m for CV_32FC1 "
      "depth) on 'topic', with a sensor_msgs/msg/CameraInfo of the frame's intrinsics (a "
      "rectified pinhole camera) on 'camera_info'; labels as sensor_msgs/msg/Image 16UC1 "
      "(0 = background, 1..N objects) on 'labels_topic'; objects as facet_msgs/msg/Objects on "
      "'objects_topic' (id, pixel count, centroid, oriented box, superquadric, grasp, support "
      "plane with its coefficients when planes is connected) and, for RViz, as "
      "visualization_msgs/msg/MarkerArray on 'markers_topic' (a DELETEALL, then per object a "
      "box and an ellipsoid of its superquadric's half sizes, in the overlay's colours). Each "
      "message's header has the "
      "frame's timestamp (or the time of publishing, stamp 'now') and the frame's camera "
      "frame id (the header frame_id ros2.subscribe received), or 'frame_id' for frames that "
      "carry none (files, OpenNI2). A topic is "
      "advertised when its input first has a value. wait_for_readers holds the first message "
      "of each topic until that many readers are matched (a reliable recording then loses no "
      "frame); rate_hz paces the messages like a camera. At the end a reliable publisher waits "
      "up to wait_timeout_s for its readers to acknowledge everything. Metric stamp_age_ms: "
      "the time of publishing labels minus their header stamp (publish stamp to labels out "
      "when the stamp came from a camera on this clock).");
  spec.declare(kDepth, kLabels, kObjects, kPlanes, kTopic, kCameraInfo, kLabelsTopic, kObjectsTopic,
               kMarkersTopic, kDomain, kQos, kHistoryDepth, kFrameId, kStamp, kRate,
               kWaitForReaders, kWaitTimeout)
      .concurrency(Concurrency::serial);
  return spec;
}

PublishStage::PublishStage(const Params& params)
    : depth_topic_(kTopic(params)),
      camera_info_topic_(kCameraInfo(params)),
      labels_topic_(kLabelsTopic(params)),
      objects_topic_(kObjectsTopic(params)),
      markers_topic_(kMarkersTopic(params)),
      domain_param_(kDomain(params)),
      qos_{kQos(params) == Qos::reliable, kHistoryDepth(params)},
      frame_id_(kFrameId(params)),
      stamp_now_(kStamp(params) == Stamp::now),
      rate_hz_(kRate(params)),
      wait_for_readers_(kWaitForReaders(params)),
      wait_timeout_s_(kWaitTimeout(params)) {
  if (camera_info_topic_.empty()) camera_info_topic_ = default_camera_info_topic(depth_topic_);
}

void PublishStage::open(const OpenContext& /*ctx*/) {
  // Names are checked before the first frame, so that a typo stops the run at once.
  checked_dds_name(depth_topic_, kTopic.name());
  checked_dds_name(camera_info_topic_, kCameraInfo.name());
  checked_dds_name(labels_topic_, kLabelsTopic.name());
  checked_dds_name(objects_topic_, kObjectsTopic.name());
  checked_dds_name(markers_topic_, kMarkersTopic.name());
  participant_ = create_participant(checked_domain(domain_param_));
}

PublishStage::Publication PublishStage::advertise(const dds_topic_descriptor_t& descriptor,
                                                  const std::string& ros_name) {
  Publication publication;
  publication.ros_name = ros_name;
  publication.topic = create_topic(participant_, descriptor, dds_topic_name(ros_name), ros_name);
  publication.writer = create_writer(participant_, publication.topic, qos_, ros_name);
  wait_for_readers(publication);
  return publication;
}

void PublishStage::wait_for_readers(const Publication& publication) const {
  if (wait_for_readers_ == 0) return;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(wait_timeout_s_));
  while (matched_count(publication.writer, true) < static_cast<std::uint32_t>(wait_for_readers_)) {
    if (Clock::now() >= deadline) {
      throw StageError("topic '" + publication.ros_name +
                       "': " + std::to_string(matched_count(publication.writer, true)) + " of " +
                       std::to_string(wait_for_readers_) + " readers matched within " +
                       std::to_string(wait_timeout_s_) + " s (wait_for_readers)");
    }
    std::this_thread::sleep_for(kMatchPoll);
  }
}

void PublishStage::pace() {
  if (rate_hz_ <= 0.0) return;
  const auto now = Clock::now();
  if (next_publish_ > now) std::this_thread::sleep_until(next_publish_);
  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz_));
  next_publish_ = std::max(next_publish_, now) + period;
}

void PublishStage::write(const Publication& publication, const void* message) const {
  const dds_return_t written = dds_write(publication.writer.get(), message);
  if (written < 0) {
    throw StageError("cannot publish on '" + publication.ros_name +
                     "': " + dds_error_text(written));
  }
}

void PublishStage::process(ProcessContext& ctx) {
  const DepthImage* depth = kDepth(ctx);
  const LabelImage* labels = kLabels(ctx);
  const ObjectList* objects = kObjects(ctx);
  if (depth == nullptr && labels == nullptr && objects == nullptr) return;
  pace();

  if (depth != nullptr) {
    const DepthImage& input = *depth;
    if (!input.camera.valid()) {
      throw StageError("depth of frame '" + input.frame.stem + "' has no camera intrinsics for '" +
                       camera_info_topic_ + "'");
    }
    if (!depth_.writer) depth_ = advertise(sensor_msgs_msg_dds__Image__desc, depth_topic_);
    if (!camera_info_.writer) {
      camera_info_ = advertise(sensor_msgs_msg_dds__CameraInfo__desc, camera_info_topic_);
    }
    const std::int64_t stamp_ns = stamp_now_ ? system_now_ns() : input.frame.timestamp_ns;
    // camera_info first: a subscriber that takes the image finds its info already there.
    const CameraInfoMessage info(input.camera, stamp_ns, header_frame_id(input.frame));
    write(camera_info_, &info.message());
    const ImageMessage image(input.depth, stamp_ns, header_frame_id(input.frame));
    write(depth_, &image.message());
  }

  if (labels != nullptr) {
    const LabelImage& input = *labels;
    if (!input.labels.empty()) {
      if (!labels_.writer) labels_ = advertise(sensor_msgs_msg_dds__Image__desc, labels_topic_);
      const std::int64_t stamp_ns = stamp_now_ ? system_now_ns() : input.frame.timestamp_ns;
      const ImageMessage image(labels_to_16u(input.labels), stamp_ns, header_frame_id(input.frame));
      write(labels_, &image.message());
      ctx.metric("stamp_age_ms", static_cast<double>(system_now_ns() - stamp_ns) * 1e-6);
    }
  }

  if (objects != nullptr) publish_objects(ctx, *objects);
}

void PublishStage::publish_objects(ProcessContext& ctx, const ObjectList& objects) {
  const SupportPlanes* planes = kPlanes(ctx);
  if (!objects_.writer) {
    objects_ = advertise(facet_msgs_msg_dds__Objects__desc, objects_topic_);
  }
  if (!markers_.writer) {
    markers_ = advertise(visualization_msgs_msg_dds__MarkerArray__desc, markers_topic_);
  }
  const std::int64_t stamp_ns = stamp_now_ ? system_now_ns() : objects.frame.timestamp_ns;
  const ObjectsMessage message(objects, planes, stamp_ns, header_frame_id(objects.frame));
  write(objects_, &message.message());
  const MarkerArrayMessage markers(objects, stamp_ns, header_frame_id(objects.frame));
  write(markers_, &markers.message());
}

const std::string& PublishStage::header_frame_id(const FrameInfo& frame) const {
  return frame.camera_frame_id.empty() ? frame_id_ : frame.camera_frame_id;
}

void PublishStage::flush(const Publication& publication) const {
  if (!publication.writer || !qos_.reliable) return;
  // Best effort: a reader that left or never acknowledges must not keep the run from ending.
  dds_wait_for_acks(publication.writer.get(), static_cast<dds_duration_t>(wait_timeout_s_ * 1e9));
}

void PublishStage::close() {
  for (const Publication* publication : {&camera_info_, &depth_, &labels_})
    flush(*publication);
  // A writer before its topic: Cyclone refuses to delete a topic that is still in use.
  for (Publication* publication : {&camera_info_, &depth_, &labels_, &objects_, &markers_}) {
    publication->writer.reset();
    publication->topic.reset();
  }
  participant_.reset();
}

}  // namespace facet::ros2
