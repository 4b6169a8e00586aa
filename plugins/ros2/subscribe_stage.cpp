#include "ros2/subscribe_stage.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

#include "facet/contract.hpp"
#include "facet/error.hpp"
#include "facet/types/images.hpp"
#include "ros2/depth_messages.hpp"
#include "ros2/ros_names.hpp"
#include "ros2/stage_settings.hpp"

namespace facet::ros2 {
namespace {

// Samples taken from a reader per dds_take call.
constexpr std::size_t kTakeBatch = 16;
// How long one wait on the readers lasts at most, so that the idle timeout is seen in time.
constexpr double kWaitSlice_s = 0.1;
// camera_infos kept for matching: several seconds of a 30 Hz camera.
constexpr std::size_t kInfosKept = 256;

// What a CV_32FC1 image in metres becomes.
enum class OutputUnit { mm, as_received };

const Out<DepthImage> kDepth{"depth",
                             "Depth, CV_16UC1 in mm (or CV_32FC1 in m when output_unit is "
                             "as_received), with index, stamp, stem, intrinsics and the header's "
                             "frame_id."};
const EnumParam<Qos> kQos{"qos",
                          Qos::sensor,
                          {{Qos::sensor, "sensor"}, {Qos::reliable, "reliable"}},
                          "sensor: best effort, newest frame (live cameras); reliable: reliable, "
                          "every frame in order."};
const Param<int> kHistoryDepth{
    "history_depth",
    10,
    "Samples the DDS readers keep (keep last N): with sensor the frames a slow graph "
    "can count as dropped, with reliable the frames that may queue up unread.",
    {.min = 1, .max = 1000}};
const Param<double> kIdleTimeout{"idle_timeout_s",
                                 0.0,
                                 "End of stream after this long without a message (counted from "
                                 "the start too); 0 = never.",
                                 {.unit = "s", .min = 0.0}};
const EnumParam<OutputUnit> kOutputUnit{
    "output_unit",
    OutputUnit::mm,
    {{OutputUnit::mm, "mm"}, {OutputUnit::as_received, "as_received"}},
    "mm: 32FC1 metres are converted to CV_16UC1 mm (NaN, <= 0 and beyond 65.535 m "
    "become 0); as_received: 32FC1 stays CV_32FC1 in m."};

std::string frame_stem(std::int64_t index) {
  char stem[32];
  std::snprintf(stem, sizeof(stem), "%06lld", static_cast<long long>(index));
  return stem;
}

// Takes every sample `reader` holds, in arrival order, handing each valid one to `use`. Returns
// the number of valid samples.
template <typename Message, typename Use>
std::size_t take_all(const DdsEntity& reader, Use&& use) {
  std::size_t taken = 0;
  while (true) {
    std::array<void*, kTakeBatch> samples{};  // null: Cyclone lends its own buffers
    std::array<dds_sample_info_t, kTakeBatch> infos{};
    const dds_return_t n =
        dds_take(reader.get(), samples.data(), infos.data(), kTakeBatch, kTakeBatch);
    if (n <= 0) return taken;
    // Return the loan however `use` ends.
    struct Loan {
      const DdsEntity& reader;
      std::array<void*, kTakeBatch>& samples;
      dds_return_t count;
      ~Loan() { dds_return_loan(reader.get(), samples.data(), count); }
    } loan{reader, samples, n};
    for (dds_return_t i = 0; i < n; ++i) {
      if (!infos[static_cast<std::size_t>(i)].valid_data) continue;
      use(*static_cast<const Message*>(samples[static_cast<std::size_t>(i)]));
      ++taken;
    }
    if (static_cast<std::size_t>(n) < kTakeBatch) return taken;
  }
}

}  // namespace

StageSpec SubscribeStage::spec() {
  StageSpec spec(
      "ros2.subscribe",
      "Depth frames from a ROS 2 topic over DDS (Cyclone DDS; see docs/ros2.md).\n"
      "Subscribes to a sensor_msgs/msg/Image depth topic (encoding 16UC1 in mm or 32FC1 in m) "
      "and its sensor_msgs/msg/CameraInfo, pairs them by header stamp and passes on depth with "
      "the intrinsics of K. Each frame carries its index since the start, the header stamp as "
      "timestamp and the stem NNNNNN (the index, zero-padded: name order is arrival order). "
      "qos 'sensor' (best effort; the newest frame, the ones that queued up meanwhile are "
      "dropped and counted as the metric dropped_frames) suits live cameras; 'reliable' "
      "(reliable; every frame in order) suits a recording played as a camera. The stream ends "
      "after idle_timeout_s without a message. Metrics: latency_ms (receipt minus header "
      "stamp, on this computer's clock), dropped_frames. A wrong encoding, a data size that is "
      "not step x height, a K without focal lengths or a camera_info of another size stop the "
      "run with an error naming the topic.");
  spec.declare(kDepth, kTopic, kCameraInfo, kDomain, kQos, kHistoryDepth, kIdleTimeout, kOutputUnit)
      .concurrency(Concurrency::serial);
  return spec;
}

SubscribeStage::SubscribeStage(const Params& params)
    : topic_(kTopic(params)),
      camera_info_topic_(kCameraInfo(params)),
      domain_param_(kDomain(params)),
      latest_(kQos(params) == Qos::sensor),
      qos_{!latest_, kHistoryDepth(params)},
      idle_timeout_s_(kIdleTimeout(params)),
      output_mm_(kOutputUnit(params) == OutputUnit::mm),
      // Reliable: up to a reader history of images may wait for their camera_infos.
      matcher_(static_cast<std::size_t>(kHistoryDepth(params)) + 1, kInfosKept) {
  if (camera_info_topic_.empty()) camera_info_topic_ = default_camera_info_topic(topic_);
}

void SubscribeStage::open(const OpenContext& /*ctx*/) {
  const std::string image_dds = checked_dds_name(topic_, kTopic.name());
  const std::string info_dds = checked_dds_name(camera_info_topic_, kCameraInfo.name());
  participant_ = create_participant(checked_domain(domain_param_));
  image_topic_ = create_topic(participant_, sensor_msgs_msg_dds__Image__desc, image_dds, topic_);
  info_topic_ = create_topic(participant_, sensor_msgs_msg_dds__CameraInfo__desc, info_dds,
                             camera_info_topic_);
  image_reader_ = create_reader(participant_, image_topic_, qos_, topic_);
  info_reader_ = create_reader(participant_, info_topic_, qos_, camera_info_topic_);
  waitset_ = DdsEntity(dds_create_waitset(participant_.get()));
  for (const DdsEntity* reader : {&image_reader_, &info_reader_}) {
    const dds_entity_t condition = dds_create_readcondition(reader->get(), DDS_ANY_STATE);
    if (condition < 0 || dds_waitset_attach(waitset_.get(), condition, 0) < 0) {
      throw StageError("cannot wait on '" + topic_ + "': " + dds_error_text(condition));
    }
  }
  last_message_ = Clock::now();
}

bool SubscribeStage::take_available() {
  const std::int64_t received_ns = system_now_ns();
  // camera_infos first, so that an image taken in the same round finds its own.
  const std::size_t infos =
      take_all<sensor_msgs_msg_dds__CameraInfo_>(info_reader_, [&](const auto& message) {
        matcher_.add_info(to_stamp_ns({message.header.stamp.sec, message.header.stamp.nanosec}),
                          decode_camera_info(message, camera_info_topic_));
      });
  const std::size_t images =
      take_all<sensor_msgs_msg_dds__Image_>(image_reader_, [&](const auto& message) {
        ReceivedImage image;
        image.stamp_ns = to_stamp_ns({message.header.stamp.sec, message.header.stamp.nanosec});
        image.frame_id = message.header.frame_id == nullptr ? "" : message.header.frame_id;
        image.depth = decode_depth(message, topic_);
        image.received_ns = received_ns;
        matcher_.add_image(std::move(image));
      });
  return infos + images > 0;
}

std::optional<MatchedFrame> SubscribeStage::next_frame() {
  return latest_ ? matcher_.take_newest() : matcher_.take_oldest();
}

void SubscribeStage::process(ProcessContext& ctx) {
  std::size_t dropped = 0;
  std::optional<MatchedFrame> frame;
  while (true) {
    if (take_available()) last_message_ = Clock::now();
    frame = next_frame();
    dropped += matcher_.take_dropped_count();
    if (frame) break;
    const double idle_s = std::chrono::duration<double>(Clock::now() - last_message_).count();
    if (idle_timeout_s_ > 0.0 && idle_s >= idle_timeout_s_) {
      ctx.end_of_stream();
      return;
    }
    double wait_s = kWaitSlice_s;
    if (idle_timeout_s_ > 0.0) wait_s = std::min(wait_s, idle_timeout_s_ - idle_s);
    const auto wait_ns =
        std::max<dds_duration_t>(static_cast<dds_duration_t>(wait_s * 1e9), DDS_MSECS(1));
    dds_waitset_wait(waitset_.get(), nullptr, 0, wait_ns);
  }
  if (matcher_.unmatched_total() > unmatched_warned_) {
    ctx.warn(std::to_string(matcher_.unmatched_total() - unmatched_warned_) +
             " depth image(s) dropped: no camera_info with their header stamp on '" +
             camera_info_topic_ + "'");
    unmatched_warned_ = matcher_.unmatched_total();
  }
  const cv::Mat& received = frame->image.depth;
  if (received.cols != frame->camera.width || received.rows != frame->camera.height) {
    throw StageError("topic '" + topic_ + "' has " + std::to_string(received.cols) + "x" +
                     std::to_string(received.rows) + " images, but '" + camera_info_topic_ +
                     "' says " + std::to_string(frame->camera.width) + "x" +
                     std::to_string(frame->camera.height));
  }
  FrameHeader header;
  header.camera = frame->camera;
  header.frame.index = delivered_;
  header.frame.timestamp_ns = frame->image.stamp_ns;
  header.frame.stem = frame_stem(delivered_);
  header.frame.camera_frame_id = std::move(frame->image.frame_id);
  DepthImage depth = DepthImage::make(header, output_mm_ && received.type() == CV_32FC1
                                                  ? metres_to_millimetres(received)
                                                  : received);
  ++delivered_;
  ctx.metric("latency_ms",
             static_cast<double>(frame->image.received_ns - frame->image.stamp_ns) * 1e-6);
  ctx.metric("dropped_frames", static_cast<double>(dropped));
  kDepth(ctx, std::move(depth));
}

void SubscribeStage::close() {
  waitset_.reset();
  info_reader_.reset();
  image_reader_.reset();
  info_topic_.reset();
  image_topic_.reset();
  participant_.reset();
}

}  // namespace facet::ros2
