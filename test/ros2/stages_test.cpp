// ros2.publish and ros2.subscribe in one process over the loopback interface: a publisher thread
// and the subscriber in the test's thread, each with its own DDS participant, as in two programs.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <thread>
#include <vector>

#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "io/label_palette.hpp"
#include "loopback_dds.hpp"
#include "ros2/dds_entities.hpp"
#include "ros2/depth_messages.hpp"
#include "ros2/object_messages.hpp"
#include "ros2/publish_stage.hpp"
#include "ros2/ros_names.hpp"
#include "ros2/subscribe_stage.hpp"

namespace facet::ros2 {
namespace {

using Overrides = std::map<std::string, ParamValue>;
using Clock = std::chrono::steady_clock;

class Ros2Stages : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_loopback_dds(); }
};

DepthImage make_depth(int index, const cv::Mat& pixels) {
  DepthImage depth;
  depth.depth = pixels;
  depth.camera = {525.0 + index, 525.0, 1.5, 0.5, pixels.cols, pixels.rows};
  depth.frame.index = index;
  depth.frame.timestamp_ns = 1'700'000'000'000'000'000 + index * 33'333'333LL;
  depth.frame.stem = "frame" + std::to_string(index);
  return depth;
}

cv::Mat pixels_mm(int index) {
  cv::Mat pixels(2, 4, CV_16UC1);
  for (int i = 0; i < 8; ++i)
    pixels.at<std::uint16_t>(i / 4, i % 4) = static_cast<std::uint16_t>(100 * index + i);
  return pixels;
}

double metric(const std::vector<Metric>& metrics, const std::string& name) {
  for (const auto& m : metrics) {
    if (m.name == name) return m.value;
  }
  ADD_FAILURE() << "no metric " << name;
  return -1.0;
}

// Publishes `frames` on `topic` once the subscriber is matched.
std::thread publish_frames(const std::string& topic, std::int64_t domain,
                           std::vector<DepthImage> frames, std::string* error) {
  return std::thread([topic, domain, frames = std::move(frames), error] {
    try {
      testing::StageRunner<PublishStage> publisher(Overrides{{"topic", topic},
                                                             {"domain", domain},
                                                             {"qos", std::string("reliable")},
                                                             {"wait_for_readers", std::int64_t{1}},
                                                             {"wait_timeout_s", 5.0}});
      for (const auto& frame : frames) {
        publisher.set_input("depth", Packet::make(frame));
        publisher.run();
      }
      publisher.close();
    } catch (const std::exception& caught) {
      *error = caught.what();
    }
  });
}

TEST_F(Ros2Stages, ReliableDeliversEveryFrameInOrderWithStampIntrinsicsAndFrameId) {
  const std::string topic = test::unique_topic("reliable");
  constexpr std::int64_t kDomain = 202;
  testing::StageRunner<SubscribeStage> subscriber(Overrides{{"topic", topic},
                                                            {"domain", kDomain},
                                                            {"qos", std::string("reliable")},
                                                            {"idle_timeout_s", 3.0}});
  std::vector<DepthImage> frames;
  for (int i = 0; i < 4; ++i)
    frames.push_back(make_depth(i, pixels_mm(i)));
  // Frames that came with a camera frame id keep it; the others get the param's default.
  frames[0].frame.camera_frame_id = "arm_camera_optical";
  frames[1].frame.camera_frame_id = "head_camera_optical";
  const std::vector<std::string> expected_frame_ids = {"arm_camera_optical", "head_camera_optical",
                                                       "camera_depth_optical_frame",
                                                       "camera_depth_optical_frame"};
  std::string publish_error;
  std::thread publisher = publish_frames(topic, kDomain, frames, &publish_error);

  for (int i = 0; i < 4; ++i) {
    subscriber.run();
    ASSERT_FALSE(subscriber.at_end_of_stream()) << "frame " << i;
    const auto& depth = subscriber.output<DepthImage>("depth");
    EXPECT_EQ(depth.frame.index, i);
    EXPECT_EQ(depth.frame.stem, "00000" + std::to_string(i));
    EXPECT_EQ(depth.frame.timestamp_ns, frames[static_cast<std::size_t>(i)].frame.timestamp_ns);
    EXPECT_EQ(depth.camera, frames[static_cast<std::size_t>(i)].camera);
    EXPECT_EQ(depth.frame.camera_frame_id, expected_frame_ids[static_cast<std::size_t>(i)]);
    ASSERT_EQ(depth.depth.type(), CV_16UC1);
    EXPECT_EQ(cv::norm(depth.depth, pixels_mm(i), cv::NORM_INF), 0.0);
    EXPECT_EQ(metric(subscriber.metrics(), "dropped_frames"), 0.0);
  }
  publisher.join();
  EXPECT_EQ(publish_error, "");
  // Nothing more comes: the stream ends after the idle timeout, not before.
  const auto start = Clock::now();
  subscriber.run();
  const double waited_s = std::chrono::duration<double>(Clock::now() - start).count();
  EXPECT_TRUE(subscriber.at_end_of_stream());
  EXPECT_GE(waited_s, 2.5);
  EXPECT_LT(waited_s, 6.0);
  subscriber.close();
}

TEST_F(Ros2Stages, MetresArriveAsMillimetresOrAsReceived) {
  const std::string topic = test::unique_topic("metres");
  constexpr std::int64_t kDomain = 203;
  testing::StageRunner<SubscribeStage> to_mm(Overrides{{"topic", topic},
                                                       {"domain", kDomain},
                                                       {"qos", std::string("reliable")},
                                                       {"idle_timeout_s", 5.0}});
  cv::Mat metres(2, 4, CV_32FC1, cv::Scalar(0.75));
  metres.at<float>(0, 0) = std::numeric_limits<float>::quiet_NaN();
  std::string publish_error;
  std::thread publisher = publish_frames(topic, kDomain, {make_depth(0, metres)}, &publish_error);
  to_mm.run();
  publisher.join();
  EXPECT_EQ(publish_error, "");
  ASSERT_FALSE(to_mm.at_end_of_stream());
  const auto& depth = to_mm.output<DepthImage>("depth");
  ASSERT_EQ(depth.depth.type(), CV_16UC1);
  EXPECT_EQ(depth.depth.at<std::uint16_t>(0, 0), 0);
  EXPECT_EQ(depth.depth.at<std::uint16_t>(1, 3), 750);
  to_mm.close();

  testing::StageRunner<SubscribeStage> as_received(
      Overrides{{"topic", topic},
                {"domain", kDomain},
                {"qos", std::string("reliable")},
                {"idle_timeout_s", 5.0},
                {"output_unit", std::string("as_received")}});
  publisher = publish_frames(topic, kDomain, {make_depth(0, metres)}, &publish_error);
  as_received.run();
  publisher.join();
  ASSERT_FALSE(as_received.at_end_of_stream());
  const auto& raw = as_received.output<DepthImage>("depth");
  ASSERT_EQ(raw.depth.type(), CV_32FC1);
  EXPECT_EQ(raw.depth.at<float>(1, 3), 0.75f);
}

// A sender that is not facet: raw messages on a topic the subscriber reads.
class RawSender {
 public:
  RawSender(std::uint32_t domain, const std::string& image_topic, const std::string& info_topic)
      : participant_(create_participant(domain)),
        image_topic_(create_topic(participant_, sensor_msgs_msg_dds__Image__desc,
                                  dds_topic_name(image_topic), image_topic)),
        info_topic_(create_topic(participant_, sensor_msgs_msg_dds__CameraInfo__desc,
                                 dds_topic_name(info_topic), info_topic)),
        image_writer_(create_writer(participant_, image_topic_, {true, 4}, image_topic)),
        info_writer_(create_writer(participant_, info_topic_, {true, 4}, info_topic)) {}

  // Waits until the subscriber's readers are matched (at most 5 s).
  bool matched() const {
    const auto deadline = Clock::now() + std::chrono::seconds(5);
    while (Clock::now() < deadline) {
      if (matched_count(image_writer_, true) > 0 && matched_count(info_writer_, true) > 0) {
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }
  void send(const sensor_msgs_msg_dds__Image_& image,
            const sensor_msgs_msg_dds__CameraInfo_& info) const {
    EXPECT_GE(dds_write(info_writer_.get(), &info), 0);
    EXPECT_GE(dds_write(image_writer_.get(), &image), 0);
  }

 private:
  DdsEntity participant_;
  DdsEntity image_topic_;
  DdsEntity info_topic_;
  DdsEntity image_writer_;
  DdsEntity info_writer_;
};

std::string subscribe_error(const std::string& topic, std::int64_t domain,
                            const std::function<void(sensor_msgs_msg_dds__Image_&,
                                                     sensor_msgs_msg_dds__CameraInfo_&)>& spoil) {
  testing::StageRunner<SubscribeStage> subscriber(Overrides{{"topic", topic},
                                                            {"domain", domain},
                                                            {"qos", std::string("reliable")},
                                                            {"idle_timeout_s", 5.0}});
  const CameraInfoMessage info(CameraIntrinsics{525.0, 525.0, 1.5, 0.5, 4, 2}, 7, "cam");
  const ImageMessage image(pixels_mm(1), 7, "cam");
  auto image_message = image.message();
  auto info_message = info.message();
  spoil(image_message, info_message);
  std::string error = "no error";
  std::thread sender([&] {
    const RawSender raw(static_cast<std::uint32_t>(domain), topic,
                        default_camera_info_topic(topic));
    if (raw.matched()) raw.send(image_message, info_message);
    // The subscriber's run() returns with its error before this thread ends: stay matched.
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  });
  try {
    subscriber.run();
  } catch (const StageError& caught) {
    error = caught.what();
  }
  sender.join();
  return error;
}

TEST_F(Ros2Stages, ANonDepthEncodingIsAnErrorNamingTheTopic) {
  const std::string topic = test::unique_topic("rgb");
  char rgb8[] = "rgb8";
  const std::string error =
      subscribe_error(topic, 204, [&](auto& image, auto&) { image.encoding = rgb8; });
  EXPECT_NE(error.find("topic '" + topic + "': image encoding 'rgb8' is not depth"),
            std::string::npos)
      << error;
}

TEST_F(Ros2Stages, AnUncalibratedCameraInfoIsAnErrorNamingItsTopic) {
  const std::string topic = test::unique_topic("uncalibrated");
  const std::string error = subscribe_error(topic, 205, [](auto&, auto& info) {
    for (double& k : info.k)
      k = 0.0;
  });
  EXPECT_NE(error.find(default_camera_info_topic(topic)), std::string::npos) << error;
  EXPECT_NE(error.find("uncalibrated"), std::string::npos) << error;
}

TEST_F(Ros2Stages, ACameraInfoOfAnotherSizeIsAnError) {
  const std::string topic = test::unique_topic("size");
  const std::string error = subscribe_error(topic, 206, [](auto&, auto& info) {
    info.width = 640;
    info.height = 480;
  });
  EXPECT_NE(error.find("has 4x2 images, but"), std::string::npos) << error;
  EXPECT_NE(error.find("says 640x480"), std::string::npos) << error;
}

TEST_F(Ros2Stages, BadTopicNamesStopBeforeTheFirstFrame) {
  testing::StageRunner<SubscribeStage> subscriber(Overrides{{"topic", std::string("/cam//depth")}});
  try {
    subscriber.run();
    ADD_FAILURE() << "a bad topic name was accepted";
  } catch (const StageError& error) {
    EXPECT_NE(std::string(error.what()).find("param 'topic'"), std::string::npos) << error.what();
  }
  testing::StageRunner<PublishStage> publisher(
      Overrides{{"labels_topic", std::string("/facet/9labels")}});
  try {
    publisher.run();
    ADD_FAILURE() << "a bad topic name was accepted";
  } catch (const StageError& error) {
    EXPECT_NE(std::string(error.what()).find("param 'labels_topic'"), std::string::npos)
        << error.what();
  }
}

TEST_F(Ros2Stages, APublisherWithoutItsReadersStopsAfterItsTimeoutNamingTheTopic) {
  const std::string topic = test::unique_topic("lonely");
  testing::StageRunner<PublishStage> publisher(Overrides{{"topic", topic},
                                                         {"domain", std::int64_t{207}},
                                                         {"wait_for_readers", std::int64_t{1}},
                                                         {"wait_timeout_s", 0.3}});
  publisher.set_input("depth", Packet::make(make_depth(0, pixels_mm(0))));
  try {
    publisher.run();
    ADD_FAILURE() << "published without a reader";
  } catch (const StageError& error) {
    EXPECT_NE(std::string(error.what()).find("topic '" + topic + "': 0 of 1 readers matched"),
              std::string::npos)
        << error.what();
  }
}

// Takes samples of one type from a topic, as RViz or a grasp planner would.
template <typename Message>
class RawReader {
 public:
  RawReader(std::uint32_t domain, const dds_topic_descriptor_t& descriptor,
            const std::string& topic)
      : participant_(create_participant(domain)),
        topic_(create_topic(participant_, descriptor, dds_topic_name(topic), topic)),
        reader_(create_reader(participant_, topic_, {true, 8}, topic)) {}

  // Waits up to 5 s for one sample and copies what `use` needs from it.
  template <typename Use>
  bool take_one(Use&& use) {
    const auto deadline = Clock::now() + std::chrono::seconds(5);
    while (Clock::now() < deadline) {
      void* samples[1] = {nullptr};
      dds_sample_info_t info{};
      const dds_return_t n = dds_take(reader_.get(), samples, &info, 1, 1);
      if (n == 1) {
        if (info.valid_data) use(*static_cast<const Message*>(samples[0]));
        dds_return_loan(reader_.get(), samples, n);
        if (info.valid_data) return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

 private:
  DdsEntity participant_;
  DdsEntity topic_;
  DdsEntity reader_;
};

TEST_F(Ros2Stages, ObjectsGoOutAsFacetMessagesAndRvizMarkers) {
  constexpr std::int64_t kDomain = 208;
  const std::string objects_topic = test::unique_topic("objects");
  const std::string markers_topic = test::unique_topic("markers");
  RawReader<facet_msgs_msg_dds__Objects_> objects_reader(kDomain, facet_msgs_msg_dds__Objects__desc,
                                                         objects_topic);
  RawReader<visualization_msgs_msg_dds__MarkerArray_> markers_reader(
      kDomain, visualization_msgs_msg_dds__MarkerArray__desc, markers_topic);

  ObjectList objects;
  objects.frame.timestamp_ns = 42'000'000'007;
  ObjectModel cup;
  cup.id = 1;
  cup.pixel_count = 1234;
  cup.centroid_m = {0.1, -0.05, 0.8};
  cup.box.pose = Eigen::Translation3d(0.1, -0.05, 0.8) *
                 Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitZ());
  cup.box.half_extents_m = {0.04, 0.04, 0.06};
  cup.superquadric.valid = true;
  cup.superquadric.pose = cup.box.pose;
  cup.superquadric.size_m = {0.035, 0.035, 0.055};
  cup.superquadric.epsilon1 = 0.3;
  cup.superquadric.epsilon2 = 1.0;
  cup.support_plane = 2;
  cup.grasp = GraspPrototype::power;
  ObjectModel flat = cup;  // no superquadric, a flat box
  flat.id = 2;
  flat.superquadric.valid = false;
  flat.box.half_extents_m = {0.1, 0.1, 0.0};
  flat.grasp = GraspPrototype::pincer;
  objects.objects = {cup, flat};
  SupportPlanes planes;
  Plane table;
  table.id = 2;
  table.normal = {0.0, -0.8, -0.6};
  table.offset_m = 0.7;
  planes.planes = {table};

  testing::StageRunner<PublishStage> publisher(Overrides{{"objects_topic", objects_topic},
                                                         {"markers_topic", markers_topic},
                                                         {"domain", kDomain},
                                                         {"frame_id", std::string("optical")},
                                                         {"wait_for_readers", std::int64_t{1}},
                                                         {"wait_timeout_s", 5.0}});
  publisher.set_input("objects", Packet::make(objects));
  publisher.set_input("planes", Packet::make(planes));
  publisher.run();

  ASSERT_TRUE(objects_reader.take_one([&](const facet_msgs_msg_dds__Objects_& message) {
    EXPECT_EQ(message.header.stamp.sec, 42);
    EXPECT_EQ(message.header.stamp.nanosec, 7u);
    EXPECT_STREQ(message.header.frame_id, "optical");
    ASSERT_EQ(message.objects._length, 2u);
    const auto& first = message.objects._buffer[0];
    EXPECT_EQ(first.id, 1);
    EXPECT_EQ(first.pixel_count, 1234);
    EXPECT_EQ(first.centroid.z, 0.8);
    EXPECT_NEAR(first.box_pose.orientation.z, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(first.box_pose.orientation.w, std::sqrt(0.5), 1e-12);
    EXPECT_EQ(first.box_half_extents.z, 0.06);
    EXPECT_TRUE(first.superquadric_valid);
    EXPECT_EQ(first.superquadric_size.x, 0.035);
    EXPECT_EQ(first.superquadric_epsilon1, 0.3);
    EXPECT_STREQ(first.grasp, "power");
    EXPECT_EQ(first.support_plane, 2);
    EXPECT_EQ(first.support_normal.y, -0.8);
    EXPECT_EQ(first.support_offset, 0.7);
    EXPECT_FALSE(message.objects._buffer[1].superquadric_valid);
    EXPECT_STREQ(message.objects._buffer[1].grasp, "pincer");
  }));
  ASSERT_TRUE(markers_reader.take_one([&](const visualization_msgs_msg_dds__MarkerArray_& message) {
    // DELETEALL, the cup's box and ellipsoid, the flat object's box.
    ASSERT_EQ(message.markers._length, 4u);
    const auto* markers = message.markers._buffer;
    EXPECT_EQ(markers[0].action, MarkerArrayMessage::kDeleteAll);
    EXPECT_EQ(markers[1].type, MarkerArrayMessage::kCube);
    EXPECT_STREQ(markers[1].ns, "facet_boxes");
    EXPECT_EQ(markers[1].id, 1);
    EXPECT_EQ(markers[1].scale.z, 0.12);
    EXPECT_STREQ(markers[1].header.frame_id, "optical");
    const io::Rgb colour = io::label_colour(1);
    EXPECT_FLOAT_EQ(markers[1].color.r, static_cast<float>(colour.r) / 255.0f);
    EXPECT_FLOAT_EQ(markers[1].color.b, static_cast<float>(colour.b) / 255.0f);
    EXPECT_EQ(markers[2].type, MarkerArrayMessage::kSphere);
    EXPECT_STREQ(markers[2].ns, "facet_superquadrics");
    EXPECT_EQ(markers[2].scale.x, 0.07);
    EXPECT_EQ(markers[3].id, 2);
    EXPECT_EQ(markers[3].type, MarkerArrayMessage::kCube);
    EXPECT_EQ(markers[3].scale.z, 0.001) << "a flat box is drawn 1 mm thick";
  }));
  publisher.close();
}

}  // namespace
}  // namespace facet::ros2
