// What facet puts on the wire, byte for byte, against sequences built by hand from the CDR rules
// (XCDR1, little endian, as rmw_cyclonedds sends ROS 2 messages), and the reverse: bytes built
// by hand decode into the expected depth and intrinsics. So compatibility with ROS 2 does not
// rest on facet talking to itself.
//
// The rules used: a 4-byte encapsulation header {0x00, 0x01} (CDR_LE) and two option bytes;
// then the fields in declaration order, each aligned to its own size (up to 8, counted from the
// end of the header); a string is a uint32 length including the terminating NUL, the characters
// and the NUL; a sequence is a uint32 element count and the elements; an array is its elements.

#include <dds/dds.h>
#include <dds/ddsi/ddsi_serdata.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <opencv2/core.hpp>
#include <vector>

#include "facet/error.hpp"
#include "loopback_dds.hpp"
#include "ros2/dds_entities.hpp"
#include "ros2/depth_messages.hpp"

namespace facet::ros2 {
namespace {

using Bytes = std::vector<std::uint8_t>;

// Appends values in little endian with CDR alignment, counted from the start of the body.
class CdrBuilder {
 public:
  CdrBuilder() : bytes_{0x00, 0x01, 0x00, 0x00} {}

  void align(std::size_t size) {
    while ((bytes_.size() - kHeader) % size != 0)
      bytes_.push_back(0x00);
  }
  template <typename T>
  void put(T value) {
    align(sizeof(T));
    std::uint8_t raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));  // the test machine is little endian (checked below)
    bytes_.insert(bytes_.end(), raw, raw + sizeof(T));
  }
  void put_string(const std::string& text) {
    put<std::uint32_t>(static_cast<std::uint32_t>(text.size() + 1));
    bytes_.insert(bytes_.end(), text.begin(), text.end());
    bytes_.push_back(0x00);
  }
  // The serialized payload ends on a multiple of 4 bytes; the padding count is in the last two
  // bits of the option bytes (DDS-XTypes 1.3, 7.6.3.1.2, which Cyclone applies to XCDR1 too).
  Bytes finish() {
    const std::size_t padding = (4 - (bytes_.size() - kHeader) % 4) % 4;
    bytes_.insert(bytes_.end(), padding, 0x00);
    bytes_[3] = static_cast<std::uint8_t>(padding);
    return bytes_;
  }

 private:
  static constexpr std::size_t kHeader = 4;
  Bytes bytes_;
};

void put_header(CdrBuilder& cdr, std::int32_t sec, std::uint32_t nanosec, const std::string& id) {
  cdr.put<std::int32_t>(sec);
  cdr.put<std::uint32_t>(nanosec);
  cdr.put_string(id);
}

// 2x3 16UC1 pixels 1..6, stamped 5 s + 250 ns, frame "cam".
Bytes image_by_hand() {
  CdrBuilder cdr;
  put_header(cdr, 5, 250, "cam");
  cdr.put<std::uint32_t>(2);   // height
  cdr.put<std::uint32_t>(3);   // width
  cdr.put_string("16UC1");     // encoding: ends at an odd offset...
  cdr.put<std::uint8_t>(0);    // is_bigendian
  cdr.put<std::uint32_t>(6);   // step, after one byte of alignment
  cdr.put<std::uint32_t>(12);  // data: 12 bytes
  for (std::uint16_t value = 1; value <= 6; ++value)
    cdr.put<std::uint16_t>(value);
  return cdr.finish();
}

// fx 525, fy 526, cx 319.5, cy 239.5, 640x480, same header.
Bytes camera_info_by_hand() {
  CdrBuilder cdr;
  put_header(cdr, 5, 250, "cam");
  cdr.put<std::uint32_t>(480);
  cdr.put<std::uint32_t>(640);
  cdr.put_string("plumb_bob");
  cdr.put<std::uint32_t>(5);  // d: five coefficients, the doubles aligned to 8 (XCDR1)
  for (int i = 0; i < 5; ++i)
    cdr.put<double>(0.0);
  for (double k : {525.0, 0.0, 319.5, 0.0, 526.0, 239.5, 0.0, 0.0, 1.0})
    cdr.put<double>(k);
  for (double r : {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0})
    cdr.put<double>(r);
  for (double p : {525.0, 0.0, 319.5, 0.0, 0.0, 526.0, 239.5, 0.0, 0.0, 0.0, 1.0, 0.0}) {
    cdr.put<double>(p);
  }
  cdr.put<std::uint32_t>(0);  // binning_x
  cdr.put<std::uint32_t>(0);  // binning_y
  for (int i = 0; i < 4; ++i)
    cdr.put<std::uint32_t>(0);  // roi offsets and size
  cdr.put<std::uint8_t>(0);     // roi.do_rectify
  return cdr.finish();
}

cv::Mat test_pixels() {
  cv::Mat pixels(2, 3, CV_16UC1);
  for (int i = 0; i < 6; ++i)
    pixels.at<std::uint16_t>(i / 3, i % 3) = static_cast<std::uint16_t>(i + 1);
  return pixels;
}

CameraIntrinsics test_camera() {
  return {525.0, 526.0, 319.5, 239.5, 640, 480};
}

// One participant writing to and reading from itself: the reader gets the serialized sample,
// exactly as it would go out to other computers.
class WireTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_loopback_dds(); }

  void open(const dds_topic_descriptor_t& descriptor, const std::string& name) {
    participant_ = create_participant(kDomain);
    const std::string ros_name = test::unique_topic(name);
    topic_ = create_topic(participant_, descriptor, "rt" + ros_name, ros_name);
    const QosProfile qos{true, 4};
    reader_ = create_reader(participant_, topic_, qos, ros_name);
    writer_ = create_writer(participant_, topic_, qos, ros_name);
  }

  // Writes `message` and returns the serialized payload the reader receives; `type` is set to
  // the topic's serializer.
  Bytes round_trip(const void* message, const ddsi_sertype** type) {
    EXPECT_GE(dds_write(writer_.get(), message), 0);
    ddsi_serdata* serdata = nullptr;
    dds_sample_info_t info{};
    dds_return_t taken = 0;
    for (int attempt = 0; attempt < 200 && taken == 0; ++attempt) {
      taken = dds_takecdr(reader_.get(), &serdata, 1, &info, DDS_ANY_STATE);
      if (taken == 0) dds_sleepfor(DDS_MSECS(10));
    }
    if (taken != 1) {
      ADD_FAILURE() << "the sample did not come back: " << dds_error_text(taken);
      return {};
    }
    Bytes bytes(ddsi_serdata_size(serdata));
    ddsi_serdata_to_ser(serdata, 0, bytes.size(), bytes.data());
    *type = serdata->type;
    ddsi_serdata_unref(serdata);
    return bytes;
  }

  // Decodes hand-made bytes with the topic's own serializer into `sample`.
  static bool decode(const ddsi_sertype* type, const Bytes& bytes, void* sample) {
    ddsrt_iovec_t iov{};
    iov.iov_base = const_cast<std::uint8_t*>(bytes.data());
    iov.iov_len = static_cast<ddsrt_iov_len_t>(bytes.size());
    ddsi_serdata* serdata = ddsi_serdata_from_ser_iov(type, SDK_DATA, 1, &iov, bytes.size());
    if (serdata == nullptr) return false;
    const bool ok = ddsi_serdata_to_sample(serdata, sample, nullptr, nullptr);
    ddsi_serdata_unref(serdata);
    return ok;
  }

  static constexpr std::uint32_t kDomain = 201;
  DdsEntity participant_;
  DdsEntity topic_;
  DdsEntity reader_;
  DdsEntity writer_;
};

TEST_F(WireTest, ImageBytesAreTheCdrRulesBytes) {
  ASSERT_EQ(std::endian::native, std::endian::little) << "the expected bytes are little endian";
  EXPECT_STREQ(sensor_msgs_msg_dds__Image__desc.m_typename, "sensor_msgs::msg::dds_::Image_");
  open(sensor_msgs_msg_dds__Image__desc, "cdr_image");
  const ImageMessage message(test_pixels(), 5'000'000'250, "cam");
  const ddsi_sertype* type = nullptr;
  const Bytes wire = round_trip(&message.message(), &type);
  EXPECT_EQ(wire, image_by_hand());

  sensor_msgs_msg_dds__Image_ decoded{};
  ASSERT_TRUE(decode(type, image_by_hand(), &decoded));
  const cv::Mat depth = decode_depth(decoded, "test");
  EXPECT_EQ(decoded.header.stamp.sec, 5);
  EXPECT_EQ(decoded.header.stamp.nanosec, 250u);
  EXPECT_STREQ(decoded.header.frame_id, "cam");
  EXPECT_EQ(cv::norm(depth, test_pixels(), cv::NORM_INF), 0.0);
  dds_sample_free(&decoded, &sensor_msgs_msg_dds__Image__desc, DDS_FREE_CONTENTS);
}

TEST_F(WireTest, CameraInfoBytesAreTheCdrRulesBytes) {
  EXPECT_STREQ(sensor_msgs_msg_dds__CameraInfo__desc.m_typename,
               "sensor_msgs::msg::dds_::CameraInfo_");
  open(sensor_msgs_msg_dds__CameraInfo__desc, "cdr_camera_info");
  const CameraInfoMessage message(test_camera(), 5'000'000'250, "cam");
  const ddsi_sertype* type = nullptr;
  const Bytes wire = round_trip(&message.message(), &type);
  EXPECT_EQ(wire, camera_info_by_hand());

  sensor_msgs_msg_dds__CameraInfo_ decoded{};
  ASSERT_TRUE(decode(type, camera_info_by_hand(), &decoded));
  EXPECT_EQ(decode_camera_info(decoded, "test"), test_camera());
  dds_sample_free(&decoded, &sensor_msgs_msg_dds__CameraInfo__desc, DDS_FREE_CONTENTS);
}

}  // namespace
}  // namespace facet::ros2
