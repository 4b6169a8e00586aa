// The ros2 plugin: a facet graph as a participant of a ROS 2 network, through Cyclone DDS.
#include "facet/plugin.hpp"

#include "ros2/publish_stage.hpp"
#include "ros2/subscribe_stage.hpp"

FACET_PLUGIN("facet_ros2", "0.1.0") {
  registrar.add<facet::ros2::SubscribeStage>();
  registrar.add<facet::ros2::PublishStage>();
}
