// partition.graph's step pairs (graph_steps.hpp) on hand-made nodes.

#include "partition/graph_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace facet::test {
namespace {

using partition::find_step_pairs;
using partition::GraphNode;
using partition::GraphNodes;
using partition::StepRule;
using partition::TouchingNodes;

// A planar node on the plane through `centroid` with normal `normal` (made unit).
GraphNode planar_node(Eigen::Vector3f normal, const Eigen::Vector3f& centroid, bool planar = true) {
  GraphNode node;
  node.segment = 0;
  node.patch = 1;
  node.planar = planar;
  normal.normalize();
  static_cast<algo::Plane&>(node.plane) = algo::Plane::through(normal, centroid);
  node.plane.centroid_m = centroid;
  node.plane.valid = true;
  return node;
}

// Two fronts facing the camera (normal -z), the second `step_m` further away and 10 cm to the
// side, touching in the image.
GraphNodes two_fronts(double step_m, double tilt_deg = 0.0, bool planar = true) {
  GraphNodes graph;
  graph.nodes.push_back(planar_node({0.0F, 0.0F, -1.0F}, {-0.05F, 0.0F, 1.0F}));
  const auto tilt = static_cast<float>(tilt_deg * std::numbers::pi / 180.0);
  graph.nodes.push_back(planar_node({std::sin(tilt), 0.0F, -std::cos(tilt)},
                                    {0.05F, 0.0F, 1.0F + static_cast<float>(step_m)}, planar));
  return graph;
}

const TouchingNodes kTouching{{1}, {0}};
const TouchingNodes kApart{{}, {}};

StepRule rule(double min_offset_m) {
  StepRule r;
  r.min_offset_m = min_offset_m;
  return r;
}

TEST(GraphSteps, ParallelFacesAStepApartArePaired) {
  const auto pairs = find_step_pairs(two_fronts(0.02), kTouching, rule(0.006));
  ASSERT_EQ(pairs.size(), 1U);
  EXPECT_EQ(pairs[0].first, 0);
  EXPECT_EQ(pairs[0].second, 1);
}

TEST(GraphSteps, OnePlaneBrokenInTwoIsNoStep) {
  EXPECT_TRUE(find_step_pairs(two_fronts(0.002), kTouching, rule(0.006)).empty());
  // A few degrees between the fitted normals move the far centroid off the other's plane, but
  // not the near one: the smaller offset decides.
  EXPECT_TRUE(find_step_pairs(two_fronts(0.0, 4.0), kTouching, rule(0.006)).empty());
}

TEST(GraphSteps, NeedsTouchingParallelPlanarFacesAndAnOffset) {
  EXPECT_TRUE(find_step_pairs(two_fronts(0.02), kApart, rule(0.006)).empty());
  EXPECT_TRUE(find_step_pairs(two_fronts(0.02, 40.0), kTouching, rule(0.006)).empty());
  EXPECT_TRUE(find_step_pairs(two_fronts(0.02, 0.0, false), kTouching, rule(0.006)).empty());
  EXPECT_TRUE(find_step_pairs(two_fronts(0.02), kTouching, rule(0.0)).empty());  // off
}

}  // namespace
}  // namespace facet::test
