// Delta_blob grows with the square of the depth beyond distance_growth_start_m, so that a far
// surface in a depth camera's depth steps stays one blob.
#include "facet/algo/neighbour_gate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "blobs/euclidean_regions.hpp"

namespace facet::test {
namespace {

using algo::NeighbourGate;
using algo::RegionSizeRule;

TEST(NeighbourGate, GrowsWithTheSquareOfTheDepthBeyondItsStart) {
  const NeighbourGate gate(0.01F, 1.2F);
  const float near_a[3] = {0.0F, 0.0F, 1.0F};
  const float near_b[3] = {0.0F, 0.0F, 1.011F};
  EXPECT_FALSE(gate.close(near_a, near_b));  // 10 mm at 1 m
  const float far_a[3] = {0.0F, 0.0F, 2.4F};
  const float far_b[3] = {0.0F, 0.0F, 2.435F};
  EXPECT_TRUE(gate.close(far_a, far_b));  // 40 mm at 2.4 m
  const float farther_b[3] = {0.0F, 0.0F, 2.445F};
  EXPECT_FALSE(gate.close(far_a, farther_b));
  const NeighbourGate fixed(0.01F, 0.0F);
  EXPECT_FALSE(fixed.close(far_a, far_b));
}

// A plane seen at 2.2-2.8 m whose depth comes in Kinect disparity steps (1/8 px of a 580 px,
// 7.5 cm baseline sensor: 12-20 mm apart there): one region with the growing distance, stripes
// with the paper's fixed 10 mm.
TEST(NeighbourGate, FarPlaneInDepthStepsIsOneRegion) {
  const int rows = 120;
  const int cols = 160;
  cv::Mat xyz(rows, cols, CV_32FC3);
  const double f = 525.0;
  for (int v = 0; v < rows; ++v) {
    for (int u = 0; u < cols; ++u) {
      const double exact = 2.2 + 0.6 * v / rows;  // a floor seen at a slant
      const double steps = std::round(8.0 * 580.0 * 0.075 / exact);
      const double z = 8.0 * 580.0 * 0.075 / steps;
      xyz.at<cv::Vec3f>(v, u) =
          cv::Vec3f(static_cast<float>((u - cols / 2) * z / f),
                    static_cast<float>((v - rows / 2) * z / f), static_cast<float>(z));
    }
  }
  const cv::Mat mask(rows, cols, CV_8UC1, cv::Scalar(1));
  const auto growing = blobs::grow_euclidean_regions(mask, xyz, NeighbourGate(0.01F, 1.2F),
                                                     RegionSizeRule{1, 0.0, 1});
  EXPECT_EQ(growing.count, 1);
  const auto fixed = blobs::grow_euclidean_regions(mask, xyz, NeighbourGate(0.01F, 0.0F),
                                                   RegionSizeRule{1, 0.0, 1});
  EXPECT_GT(fixed.count, 10);
}

}  // namespace
}  // namespace facet::test
