#include "facet/types/geometry.hpp"

#include <gtest/gtest.h>

namespace {

TEST(Geometry, PlaneSignedDistance) {
  facet::Plane table;
  table.normal = Eigen::Vector3d(0, -1, 0);  // facing up, towards a camera above it
  table.offset_m = 0.5;                      // y = 0.5 m below the camera
  EXPECT_NEAR(table.signed_distance_m({0.1, 0.4, 1.0}), 0.1, 1e-12);     // 10 cm above
  EXPECT_NEAR(table.signed_distance_m({0.0, 0.5, 2.0}), 0.0, 1e-12);     // on it
  EXPECT_NEAR(table.signed_distance_m({0.0, 0.55, 2.0}), -0.05, 1e-12);  // below
}

TEST(Geometry, ObjectListTravelsAsAPacket) {
  facet::ObjectList list;
  list.objects.push_back({});
  list.objects.back().grasp = facet::GraspPrototype::pincer;
  const auto packet = facet::Packet::make(list);
  EXPECT_EQ(packet.type_key(), "facet.ObjectList/2");
  ASSERT_NE(packet.get_if<facet::ObjectList>(), nullptr);
  EXPECT_EQ(facet::to_string(packet.get_if<facet::ObjectList>()->objects[0].grasp), "pincer");
}

}  // namespace
