// Edge pixels into blobs (grow.blobs edge_pixels): they join the blob they connect to without
// joining two blobs, edge-only objects become blobs when large enough, and a depth jump stops
// them.
#include "blobs/edge_attachment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <vector>

namespace {

using facet::blobs::attach_edge_pixels;
using facet::blobs::EuclideanRegions;
using facet::blobs::grow_euclidean_regions;

constexpr float kDistanceM = 0.01F;

// A fronto-parallel surface at z_m, 1 mm between neighbouring pixels.
cv::Mat flat_points(int rows, int cols, float z_m) {
  cv::Mat xyz(rows, cols, CV_32FC3);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x)
      xyz.at<cv::Vec3f>(y, x) = {0.001F * static_cast<float>(x), 0.001F * static_cast<float>(y),
                                 z_m};
  return xyz;
}

EuclideanRegions blobs_of(const cv::Mat& patch_mask, const cv::Mat& xyz) {
  return grow_euclidean_regions(patch_mask, xyz, facet::algo::NeighbourGate(kDistanceM, 0.0F),
                                facet::algo::RegionSizeRule{1, 0.0, 1});
}

// attach_edge_pixels with the edge pixels listed in raster order, as grow.blobs lists them.
facet::blobs::EdgeAttachment attach(EuclideanRegions& blobs, const cv::Mat& edges,
                                    const cv::Mat& xyz, std::int64_t min_size_px) {
  std::vector<std::int32_t> pixels;
  for (int i = 0; i < static_cast<int>(edges.total()); ++i) {
    if (edges.ptr<std::uint8_t>()[i] != 0) pixels.push_back(i);
  }
  const facet::algo::RegionSizeRule size{min_size_px, 0.0, min_size_px};
  return attach_edge_pixels(blobs, edges, pixels, xyz, facet::algo::NeighbourGate(kDistanceM, 0.0F),
                            min_size_px < 0 ? nullptr : &size);
}

TEST(EdgeAttachment, AnEdgeBandBetweenTwoBlobsIsSharedAndKeepsThemApart) {
  // Columns 0-9 and 16-25 are patches, 10-15 an edge band: its closer half goes to each side.
  const cv::Mat xyz = flat_points(8, 26, 1.0F);
  cv::Mat patches(8, 26, CV_8UC1, cv::Scalar(0));
  patches.colRange(0, 10).setTo(1);
  patches.colRange(16, 26).setTo(1);
  cv::Mat edges(8, 26, CV_8UC1, cv::Scalar(0));
  edges.colRange(10, 16).setTo(1);

  EuclideanRegions blobs = blobs_of(patches, xyz);
  ASSERT_EQ(blobs.count, 2);
  const auto result = attach(blobs, edges, xyz, 5);
  EXPECT_EQ(blobs.count, 2);
  EXPECT_EQ(result.attached_px, 8 * 6);
  EXPECT_EQ(result.edge_only_blobs, 0);
  for (int y = 0; y < 8; ++y) {
    EXPECT_EQ(blobs.labels.at<std::int32_t>(y, 12), 1) << y;
    EXPECT_EQ(blobs.labels.at<std::int32_t>(y, 13), 2) << y;
  }
}

TEST(EdgeAttachment, EdgeOnlyObjectsBecomeBlobsWhenLargeEnough) {
  // One patch blob on the left; two edge-only regions apart from it: 6x6 and 2x2 pixels.
  const cv::Mat xyz = flat_points(20, 40, 1.0F);
  cv::Mat patches(20, 40, CV_8UC1, cv::Scalar(0));
  patches(cv::Rect(0, 0, 10, 10)).setTo(1);
  cv::Mat edges(20, 40, CV_8UC1, cv::Scalar(0));
  edges(cv::Rect(20, 5, 6, 6)).setTo(1);
  edges(cv::Rect(33, 15, 2, 2)).setTo(1);

  EuclideanRegions blobs = blobs_of(patches, xyz);
  const auto result = attach(blobs, edges, xyz, 10);
  EXPECT_EQ(result.attached_px, 0);
  EXPECT_EQ(result.edge_only_blobs, 1);
  EXPECT_EQ(blobs.count, 2);
  EXPECT_EQ(blobs.labels.at<std::int32_t>(0, 0), 1);
  EXPECT_EQ(blobs.labels.at<std::int32_t>(7, 22), 2);
  EXPECT_EQ(blobs.labels.at<std::int32_t>(15, 33), 0);  // 4 px: under min_size_px
}

TEST(EdgeAttachment, WithoutASizeRuleNoEdgeOnlyBlobsAreMade) {
  // grow.blobs asks for none when no support plane was found.
  const cv::Mat xyz = flat_points(20, 40, 1.0F);
  cv::Mat patches(20, 40, CV_8UC1, cv::Scalar(0));
  patches(cv::Rect(0, 0, 10, 10)).setTo(1);
  cv::Mat edges(20, 40, CV_8UC1, cv::Scalar(0));
  edges(cv::Rect(10, 0, 2, 10)).setTo(1);   // touches the blob: joins it
  edges(cv::Rect(20, 5, 12, 12)).setTo(1);  // apart: stays out
  EuclideanRegions blobs = blobs_of(patches, xyz);
  const auto result = attach(blobs, edges, xyz, -1);
  EXPECT_EQ(result.attached_px, 20);
  EXPECT_EQ(result.edge_only_blobs, 0);
  EXPECT_EQ(blobs.count, 1);
  EXPECT_EQ(cv::countNonZero(blobs.labels), 120);
}

TEST(EdgeAttachment, IdsStayInRasterOrderOfTheFirstPixel) {
  // The edge-only region starts above the patch blob, so it takes id 1.
  const cv::Mat xyz = flat_points(20, 20, 1.0F);
  cv::Mat patches(20, 20, CV_8UC1, cv::Scalar(0));
  patches(cv::Rect(0, 12, 8, 8)).setTo(1);
  cv::Mat edges(20, 20, CV_8UC1, cv::Scalar(0));
  edges(cv::Rect(12, 0, 6, 6)).setTo(1);

  EuclideanRegions blobs = blobs_of(patches, xyz);
  attach(blobs, edges, xyz, 5);
  EXPECT_EQ(blobs.count, 2);
  EXPECT_EQ(blobs.labels.at<std::int32_t>(0, 12), 1);
  EXPECT_EQ(blobs.labels.at<std::int32_t>(12, 0), 2);
}

TEST(EdgeAttachment, ADepthJumpStopsTheAttachment) {
  // Edge pixels 5 cm behind the patch next to them (background seen past a silhouette).
  cv::Mat xyz = flat_points(10, 20, 1.0F);
  for (int y = 0; y < 10; ++y)
    for (int x = 10; x < 20; ++x)
      xyz.at<cv::Vec3f>(y, x)[2] = 1.05F;
  cv::Mat patches(10, 20, CV_8UC1, cv::Scalar(0));
  patches.colRange(0, 10).setTo(1);
  cv::Mat edges(10, 20, CV_8UC1, cv::Scalar(0));
  edges.colRange(10, 13).setTo(1);

  EuclideanRegions blobs = blobs_of(patches, xyz);
  const auto result = attach(blobs, edges, xyz, 100);
  EXPECT_EQ(result.attached_px, 0);
  EXPECT_EQ(blobs.count, 1);
  EXPECT_EQ(cv::countNonZero(blobs.labels), 100);
}

// grow.blobs' min_size_reference_depth_m: a 12 x 12 region (144 px) under min_px 200 is kept
// where the area 200 px cover at 1 m needs no more (from 1.18 m on, 200 / 1.18^2 = 143.6), never
// under the floor of 100 px, and nowhere without the rule; patch blobs and edge-only blobs alike.
TEST(BlobSize, FarBlobsNeedOnlyTheAreaNearOnesNeed) {
  const facet::algo::RegionSizeRule by_area{200, 1.0, 100};
  const facet::algo::RegionSizeRule fixed{200, 0.0, 100};
  const facet::algo::RegionSizeRule high_floor{200, 1.0, 150};
  cv::Mat square(30, 30, CV_8UC1, cv::Scalar(0));
  square(cv::Rect(8, 8, 12, 12)).setTo(1);
  const cv::Mat none(30, 30, CV_8UC1, cv::Scalar(0));
  const facet::algo::NeighbourGate gate(kDistanceM, 0.0F);
  // As a blob of patch pixels (edge_only false) or of edge pixels alone.
  const auto kept = [&](float depth_m, const facet::algo::RegionSizeRule& size, bool edge_only) {
    const cv::Mat xyz = flat_points(30, 30, depth_m);
    EuclideanRegions blobs = grow_euclidean_regions(edge_only ? none : square, xyz, gate, size);
    if (!edge_only) return blobs.count == 1;
    std::vector<std::int32_t> pixels;
    for (int i = 0; i < static_cast<int>(square.total()); ++i) {
      if (square.ptr<std::uint8_t>()[i] != 0) pixels.push_back(i);
    }
    return attach_edge_pixels(blobs, square, pixels, xyz, gate, &size).edge_only_blobs == 1;
  };
  for (const bool edge_only : {false, true}) {
    SCOPED_TRACE(edge_only ? "edge-only blob" : "patch blob");
    EXPECT_FALSE(kept(1.0F, by_area, edge_only));
    EXPECT_FALSE(kept(1.15F, by_area, edge_only));  // needs 151 px
    EXPECT_TRUE(kept(1.2F, by_area, edge_only));    // needs 139 px
    EXPECT_TRUE(kept(3.0F, by_area, edge_only));    // needs 22 px: the floor's 100
    EXPECT_FALSE(kept(3.0F, fixed, edge_only));
    EXPECT_FALSE(kept(3.0F, high_floor, edge_only));
  }
}

}  // namespace
