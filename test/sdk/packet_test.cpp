#include "facet/packet.hpp"

#include <gtest/gtest.h>

#include "facet/types/images.hpp"

namespace {

struct Unrelated {
  int value = 0;
};

}  // namespace

FACET_TYPE_KEY(Unrelated, "test.Unrelated/1");

namespace {

TEST(Packet, EmptyByDefault) {
  const facet::Packet packet;
  EXPECT_TRUE(packet.empty());
  EXPECT_EQ(packet.get_if<facet::DepthImage>(), nullptr);
  EXPECT_EQ(packet.shared_as<facet::DepthImage>(), nullptr);
}

TEST(Packet, CarriesItsTypeKey) {
  const auto packet = facet::Packet::make(facet::DepthImage{});
  EXPECT_EQ(packet.type_key(), "facet.DepthImage/1");
  EXPECT_NE(packet.get_if<facet::DepthImage>(), nullptr);
  EXPECT_EQ(packet.get_if<facet::LabelImage>(), nullptr);
  EXPECT_EQ(packet.get_if<Unrelated>(), nullptr);
}

TEST(Packet, CopiesShareOnePayload) {
  facet::DepthImage depth;
  depth.depth = cv::Mat(480, 640, CV_16UC1, cv::Scalar(1000));
  const auto first = facet::Packet::make(std::move(depth));
  const facet::Packet second = first;  // fan-out: a copy of the handle, not of the image
  EXPECT_EQ(first.address(), second.address());
  EXPECT_EQ(first.get_if<facet::DepthImage>()->depth.data,
            second.get_if<facet::DepthImage>()->depth.data);
  EXPECT_EQ(first.shared_as<facet::DepthImage>().use_count(), 3);  // first, second, this one
}

TEST(Packet, KeysAreComparedByContentNotAddress) {
  // Plugins each hold their own copy of the key literal; equality must not depend on which.
  const std::string copy = std::string(facet::type_key<facet::DepthImage>());
  EXPECT_EQ(copy, facet::Packet::make(facet::DepthImage{}).type_key());
}

}  // namespace

namespace {

// Any payload derived from FrameHeader shows its frame through the packet, whatever its type, so
// the executor needs no image type to name a frame's files.
TEST(Packet, ShowsTheFrameOfAPayloadThatCarriesOne) {
  facet::LabelImage labels;
  labels.frame.index = 7;
  labels.frame.stem = "learn7";
  const auto packet = facet::Packet::make(labels);
  ASSERT_NE(packet.header(), nullptr);
  EXPECT_EQ(packet.header()->frame.stem, "learn7");
  EXPECT_EQ(packet.header()->frame.index, 7);
  // The header is the payload's own, not a copy.
  EXPECT_EQ(static_cast<const void*>(packet.header()),
            static_cast<const void*>(packet.get_if<facet::LabelImage>()));
  EXPECT_EQ(facet::Packet::make(Unrelated{}).header(), nullptr);
  EXPECT_EQ(facet::Packet().header(), nullptr);
}

}  // namespace
