#include "ros2/object_messages.hpp"

#include <algorithm>

#include "io/label_palette.hpp"

namespace facet::ros2 {
namespace {

// RViz refuses markers with a zero scale: a flat box is drawn 1 mm thick.
constexpr double kMinMarkerScale_m = 0.001;
constexpr float kBoxAlpha = 0.5f;
constexpr float kSuperquadricAlpha = 0.8f;

geometry_msgs_msg_dds__Point_ to_point(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

geometry_msgs_msg_dds__Vector3_ to_vector(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

geometry_msgs_msg_dds__Pose_ to_pose(const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond rotation(pose.rotation());
  return {to_point(pose.translation()), {rotation.x(), rotation.y(), rotation.z(), rotation.w()}};
}

geometry_msgs_msg_dds__Vector3_ marker_scale(const Eigen::Vector3d& half_sizes_m) {
  const auto full = [](double half_m) { return std::max(2.0 * half_m, kMinMarkerScale_m); };
  return {full(half_sizes_m.x()), full(half_sizes_m.y()), full(half_sizes_m.z())};
}

std_msgs_msg_dds__ColorRGBA_ colour_of(std::int32_t id, float alpha) {
  const io::Rgb rgb = io::label_colour(static_cast<std::uint32_t>(std::max(id, 0)));
  return {static_cast<float>(rgb.r) / 255.0f, static_cast<float>(rgb.g) / 255.0f,
          static_cast<float>(rgb.b) / 255.0f, alpha};
}

}  // namespace

ObjectsMessage::ObjectsMessage(const ObjectList& objects, const SupportPlanes* planes,
                               std::int64_t stamp_ns, std::string frame_id)
    : header_(stamp_ns, std::move(frame_id)) {
  header_.fill(message_.header);
  grasps_.reserve(objects.objects.size());  // no reallocation: objects_ point into it
  objects_.reserve(objects.objects.size());
  for (const ObjectModel& model : objects.objects) {
    grasps_.emplace_back(to_string(model.grasp));
    facet_msgs_msg_dds__Object_ object{};
    object.id = model.id;
    object.pixel_count = model.pixel_count;
    object.centroid = to_point(model.centroid_m);
    object.box_pose = to_pose(model.box.pose);
    object.box_half_extents = to_vector(model.box.half_extents_m);
    object.superquadric_valid = model.superquadric.valid;
    object.superquadric_pose = to_pose(model.superquadric.pose);
    object.superquadric_size = to_vector(model.superquadric.size_m);
    object.superquadric_epsilon1 = model.superquadric.epsilon1;
    object.superquadric_epsilon2 = model.superquadric.epsilon2;
    object.grasp = grasps_.back().data();
    object.support_plane = model.support_plane;
    if (planes != nullptr) {
      for (const Plane& plane : planes->planes) {
        if (plane.id != model.support_plane || model.support_plane == 0) continue;
        object.support_normal = to_vector(plane.normal);
        object.support_offset = plane.offset_m;
      }
    }
    objects_.push_back(object);
  }
  message_.objects._buffer = objects_.data();
  message_.objects._length = static_cast<std::uint32_t>(objects_.size());
  message_.objects._maximum = message_.objects._length;
  message_.objects._release = false;
}

MarkerArrayMessage::MarkerArrayMessage(const ObjectList& objects, std::int64_t stamp_ns,
                                       std::string frame_id)
    : header_(stamp_ns, std::move(frame_id)) {
  // Every string of a marker must point somewhere: Cyclone serializes what it points to.
  const auto blank = [&](std::int32_t action) {
    visualization_msgs_msg_dds__Marker_ marker{};
    header_.fill(marker.header);
    marker.ns = empty_.data();
    marker.action = action;
    marker.pose.orientation.w = 1.0;
    marker.texture_resource = empty_.data();
    marker.texture.header.frame_id = empty_.data();
    marker.texture.format = empty_.data();
    marker.text = empty_.data();
    marker.mesh_resource = empty_.data();
    marker.mesh_file.filename = empty_.data();
    return marker;
  };
  // One shape of one object: a box or the superquadric (drawn as its bounding ellipsoid).
  const auto add_shape = [&](char* ns, std::int32_t type, std::int32_t id,
                             const Eigen::Isometry3d& pose, const Eigen::Vector3d& half_extents_m,
                             float alpha) {
    auto marker = blank(kAdd);
    marker.ns = ns;
    marker.id = id;
    marker.type = type;
    marker.pose = to_pose(pose);
    marker.scale = marker_scale(half_extents_m);
    marker.color = colour_of(id, alpha);
    markers_.push_back(marker);
  };
  markers_.push_back(blank(kDeleteAll));
  for (const ObjectModel& model : objects.objects) {
    add_shape(box_namespace_.data(), kCube, model.id, model.box.pose, model.box.half_extents_m,
              kBoxAlpha);
    if (!model.superquadric.valid) continue;
    add_shape(superquadric_namespace_.data(), kSphere, model.id, model.superquadric.pose,
              model.superquadric.size_m, kSuperquadricAlpha);
  }
  message_.markers._buffer = markers_.data();
  message_.markers._length = static_cast<std::uint32_t>(markers_.size());
  message_.markers._maximum = message_.markers._length;
  message_.markers._release = false;
}

}  // namespace facet::ros2
