// partition.graph's cylinder test (cylinder_fit.hpp) on sampled surfaces: pieces of one cylinder
// fit it, pieces of two parallel cylinders, two planes and a gently bent sheet do not.

#include "partition/cylinder_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace facet::partition {
namespace {

// Points of a circular cylinder with its axis along x through (0, centre_y, centre_z), at
// angles [from, to] around it (0 = facing the camera, -z) and x in [x_from, x_to], with 1 mm of
// seeded noise on points and 5° on normals.
OrientedSamples arc(double centre_y_m, double centre_z_m, double radius_m, double from_deg,
                    double to_deg, double x_from_m, double x_to_m, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise_m(0.0, 0.001);
  std::normal_distribution<double> tilt(0.0, 5.0 * std::numbers::pi / 180.0);
  OrientedSamples out;
  for (int i = 0; i < 16; ++i) {
    const double angle = (from_deg + (to_deg - from_deg) * i / 15.0) * std::numbers::pi / 180.0;
    for (int k = 0; k < 16; ++k) {
      const double x = x_from_m + (x_to_m - x_from_m) * k / 15.0;
      const Eigen::Vector3d normal(0.0, std::sin(angle), -std::cos(angle));
      const double r = radius_m + noise_m(rng);
      out.points.emplace_back(x, centre_y_m + r * normal.y(), centre_z_m + r * normal.z());
      out.normals.push_back(
          (normal + Eigen::Vector3d(tilt(rng), tilt(rng), tilt(rng))).normalized());
    }
  }
  return out;
}

// A flat patch facing the camera at depth z_m: what the quadric fit mistook a can's pieces for.
OrientedSamples plane(double x_from_m, double z_m, unsigned seed) {
  return arc(0.0, z_m + 10.0, 10.0, -0.3, 0.3, x_from_m, x_from_m + 0.08, seed);
}

TEST(CylinderFit, TwoPiecesOfOneCanFit) {
  // A can of radius 3.5 cm, 0.75 m away, seen on both sides of an occluder 6 cm wide.
  const CylinderRule rule;
  EXPECT_TRUE(one_circular_cylinder(arc(0.0, 0.785, 0.035, -70.0, 70.0, -0.11, -0.03, 1),
                                    arc(0.0, 0.785, 0.035, -70.0, 70.0, 0.03, 0.11, 2), rule));
}

TEST(CylinderFit, TwoParallelCansDoNot) {
  const CylinderRule rule;
  EXPECT_FALSE(one_circular_cylinder(arc(0.0, 0.785, 0.035, -70.0, 70.0, -0.1, 0.1, 3),
                                     arc(0.08, 0.785, 0.035, -70.0, 70.0, -0.1, 0.1, 4), rule));
}

TEST(CylinderFit, PlanesAndGentleBendsDoNot) {
  const CylinderRule rule;
  // Two flat patches facing the camera: their normals do not turn about any axis.
  EXPECT_FALSE(one_circular_cylinder(plane(-0.11, 0.75, 5), plane(0.03, 0.76, 6), rule));
  // A sheet bent around a radius of 0.5 m: a cylinder, but wider than rule.max_radius_m.
  const OrientedSamples left = arc(0.0, 1.25, 0.5, -40.0, 40.0, -0.11, -0.03, 7);
  const OrientedSamples right = arc(0.0, 1.25, 0.5, -40.0, 40.0, 0.03, 0.11, 8);
  EXPECT_FALSE(one_circular_cylinder(left, right, rule));
  CylinderRule wide = rule;
  wide.max_radius_m = 1.0;
  EXPECT_TRUE(one_circular_cylinder(left, right, wide));
}

TEST(CylinderFit, FewSamplesAreNoEvidence) {
  OrientedSamples few = arc(0.0, 0.785, 0.035, -70.0, 70.0, -0.11, -0.03, 9);
  few.points.resize(9);
  few.normals.resize(9);
  EXPECT_FALSE(one_circular_cylinder(few, arc(0.0, 0.785, 0.035, -70.0, 70.0, 0.03, 0.11, 10),
                                     CylinderRule{}));
}

}  // namespace
}  // namespace facet::partition
