#pragma once
// facet's object list as ROS 2 messages: facet_msgs/msg/Objects for programs (a grasp planner)
// and visualization_msgs/msg/MarkerArray for RViz. Each class owns the memory its C message
// points into; dds_write serializes it at once.

#include <cstdint>
#include <string>
#include <vector>

#include "facet/types/geometry.hpp"
#include "facet_msgs.h"
#include "ros2/depth_messages.hpp"
#include "visualization_msgs.h"

namespace facet::ros2 {

// Every object with its box, superquadric, grasp and support plane. `planes` (may be null)
// gives the support planes' coefficients; without it they are 0.
class ObjectsMessage {
 public:
  ObjectsMessage(const ObjectList& objects, const SupportPlanes* planes, std::int64_t stamp_ns,
                 std::string frame_id);
  ObjectsMessage(const ObjectsMessage&) = delete;
  ObjectsMessage& operator=(const ObjectsMessage&) = delete;
  const facet_msgs_msg_dds__Objects_& message() const { return message_; }

 private:
  HeaderFields header_;
  std::vector<std::string> grasps_;
  std::vector<facet_msgs_msg_dds__Object_> objects_;
  facet_msgs_msg_dds__Objects_ message_{};
};

// What RViz draws of a frame's objects: first a DELETEALL (the previous frame's markers go),
// then per object a box (CUBE, namespace "facet_boxes") and, where the superquadric fit is
// valid, an ellipsoid of its half sizes at its pose (SPHERE, "facet_superquadrics"), in the
// colour io.overlay gives the object's id. Marker ids are object ids.
class MarkerArrayMessage {
 public:
  MarkerArrayMessage(const ObjectList& objects, std::int64_t stamp_ns, std::string frame_id);
  MarkerArrayMessage(const MarkerArrayMessage&) = delete;
  MarkerArrayMessage& operator=(const MarkerArrayMessage&) = delete;
  const visualization_msgs_msg_dds__MarkerArray_& message() const { return message_; }

  static constexpr std::int32_t kCube = 1;
  static constexpr std::int32_t kSphere = 2;
  static constexpr std::int32_t kAdd = 0;
  static constexpr std::int32_t kDeleteAll = 3;

 private:
  HeaderFields header_;
  std::string box_namespace_ = "facet_boxes";
  std::string superquadric_namespace_ = "facet_superquadrics";
  std::string empty_;
  std::vector<visualization_msgs_msg_dds__Marker_> markers_;
  visualization_msgs_msg_dds__MarkerArray_ message_{};
};

}  // namespace facet::ros2
