// Two `facet` processes over DDS on the loopback interface: graphs/ros2_camera.yaml plays the
// bundled frames as a ROS 2 camera, graphs/ros2_tabletop.yaml segments them in another process.
// The test process listens on the labels topic as a third participant would (RViz, a planner).

#include <gtest/gtest.h>

#include <chrono>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "cli_runner.hpp"
#include "loopback_dds.hpp"
#include "ros2/dds_entities.hpp"
#include "ros2/depth_messages.hpp"
#include "ros2/ros_names.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

// The bundled frames in the order io.frames plays them (natural order of their names).
const std::vector<std::string> kStems = {"learn0",  "learn5",  "learn18",
                                         "learn20", "learn27", "learn36"};

std::string facet_command(const std::string& arguments, std::int64_t domain) {
  return "env -u FACET_PLUGIN_PATH -u ROS_DOMAIN_ID CYCLONEDDS_URI=" +
         shell_quote(loopback_cyclone_config()) + " ROS_DOMAIN_ID=" + std::to_string(domain) + " " +
         shell_quote(FACET_CLI) + " " + arguments;
}

std::string graph(const std::string& name) {
  return shell_quote((source_dir() / "graphs" / name).string());
}

std::string frame_name(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06zu", index);
  return name;
}

// Label images published on `topic`, taken as they come.
class LabelsListener {
 public:
  LabelsListener(std::uint32_t domain, const std::string& topic)
      : topic_name_(topic),
        participant_(ros2::create_participant(domain)),
        topic_(ros2::create_topic(participant_, sensor_msgs_msg_dds__Image__desc,
                                  ros2::dds_topic_name(topic), topic)),
        reader_(ros2::create_reader(participant_, topic_, {true, 32}, topic)) {}

  std::vector<cv::Mat> take() {
    std::vector<cv::Mat> labels;
    void* samples[32] = {};
    dds_sample_info_t infos[32];
    const dds_return_t n = dds_take(reader_.get(), samples, infos, 32, 32);
    for (dds_return_t i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const auto& message = *static_cast<const sensor_msgs_msg_dds__Image_*>(samples[i]);
      labels.push_back(ros2::decode_depth(message, topic_name_));
      stamps_.push_back(
          ros2::to_stamp_ns({message.header.stamp.sec, message.header.stamp.nanosec}));
    }
    if (n > 0) dds_return_loan(reader_.get(), samples, n);
    return labels;
  }
  const std::vector<std::int64_t>& stamps() const { return stamps_; }

 private:
  std::string topic_name_;
  ros2::DdsEntity participant_;
  ros2::DdsEntity topic_;
  ros2::DdsEntity reader_;
  std::vector<std::int64_t> stamps_;
};

TEST(Ros2Loopback, ReliableDeliversEveryFrameInOrderAndLabelsEqualADirectRun) {
  use_loopback_dds();
  constexpr std::int64_t kDomain = 211;
  TempDir out("facet-ros2");
  const auto direct = run_cli("run " + graph("tabletop.yaml") +
                              " --param output=" + shell_quote((out.path() / "direct").string()));
  ASSERT_EQ(direct.exit_code, 0) << direct.out;

  const std::string topic = unique_topic("depth");
  const std::string labels_topic = unique_topic("labels");
  LabelsListener listener(static_cast<std::uint32_t>(kDomain), labels_topic);
  ChildProcess subscriber(
      facet_command("run " + graph("ros2_tabletop.yaml") + " --param topic=" + topic +
                        " --param labels_topic=" + labels_topic +
                        " --param qos=reliable --param idle_timeout_s=3 --param output=" +
                        shell_quote((out.path() / "ros2").string()),
                    kDomain),
      out.path() / "subscriber.log");
  ASSERT_TRUE(subscriber.started());
  // The camera sends its first frame once the subscriber's readers are matched.
  ChildProcess camera(facet_command("run " + graph("ros2_camera.yaml") + " --param topic=" + topic +
                                        " --set camera.wait_for_readers=1",
                                    kDomain),
                      out.path() / "camera.log");
  ASSERT_TRUE(camera.started());
  const auto camera_exit = camera.wait(30.0);
  const auto subscriber_exit = subscriber.wait(30.0);
  ASSERT_EQ(camera_exit, 0) << read_file(out.path() / "camera.log");
  ASSERT_EQ(subscriber_exit, 0) << read_file(out.path() / "subscriber.log");

  for (std::size_t i = 0; i < kStems.size(); ++i) {
    const auto received = out.path() / "ros2/labels" / (frame_name(i) + ".png");
    const auto expected = out.path() / "direct/labels" / (kStems[i] + ".png");
    ASSERT_TRUE(fs::exists(received)) << received;
    EXPECT_EQ(read_file(received), read_file(expected))
        << "frame " << i << " (" << kStems[i] << ")";
    EXPECT_TRUE(fs::exists(out.path() / "ros2/objects" / (frame_name(i) + ".json")));
  }
  EXPECT_FALSE(fs::exists(out.path() / "ros2/labels" / (frame_name(kStems.size()) + ".png")));

  // The labels went out over DDS as well, in order, one per frame, equal to the files.
  std::vector<cv::Mat> published;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (published.size() < kStems.size() && std::chrono::steady_clock::now() < deadline) {
    for (auto& labels : listener.take())
      published.push_back(std::move(labels));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(published.size(), kStems.size());
  for (std::size_t i = 0; i < kStems.size(); ++i) {
    const cv::Mat expected = cv::imread(
        (out.path() / "direct/labels" / (kStems[i] + ".png")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(expected.type(), CV_16UC1);
    EXPECT_EQ(cv::norm(published[i], expected, cv::NORM_INF), 0.0) << "frame " << i;
    if (i > 0) {
      EXPECT_GT(listener.stamps()[i], listener.stamps()[i - 1]);
    }
  }
}

}  // namespace
}  // namespace facet::test
