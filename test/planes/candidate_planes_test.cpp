// planes.support's first kernel: large patches become candidate planes, largest first, and a
// patch that holds two planes (a far table running into the wall behind it) gives both.
#include "planes/candidate_planes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

namespace facet::planes {
namespace {

// 100 × 60 pixels. Columns 0..59: a table top, the plane y = 0.5 m (camera frame, y down), 1 to
// 2 m away. Columns 60..99: a wall, the plane z = 3 m, from y = -0.5 down to 0.3 m (ending well
// above the table's plane, so that no wall point lies on it). Rows 0..4 of columns 0..9: a small
// patch.
struct Frame {
  cv::Mat labels{60, 100, CV_32SC1, cv::Scalar(0)};
  cv::Mat xyz{60, 100, CV_32FC3, cv::Scalar::all(std::numeric_limits<float>::quiet_NaN())};

  // table_id, wall_id: the patch ids of the two regions (equal: one patch spans both).
  Frame(std::int32_t table_id, std::int32_t wall_id, std::int32_t small_id = 0) {
    for (int row = 0; row < labels.rows; ++row) {
      for (int col = 0; col < labels.cols; ++col) {
        const float u = static_cast<float>(col) / 99.0F;
        const float v = static_cast<float>(row) / 59.0F;
        if (col < 60) {
          xyz.at<cv::Vec3f>(row, col) = {-0.5F + u, 0.5F, 1.0F + v};
          labels.at<std::int32_t>(row, col) = table_id;
        } else {
          xyz.at<cv::Vec3f>(row, col) = {-1.0F + 2.0F * u, -0.5F + 0.8F * v, 3.0F};
          labels.at<std::int32_t>(row, col) = wall_id;
        }
        if (small_id != 0 && row < 5 && col < 10) labels.at<std::int32_t>(row, col) = small_id;
      }
    }
  }
};

CandidateRule rule_for_the_frame() {
  CandidateRule rule;
  rule.min_px = 500;
  rule.off_plane_m = 0.02F;
  rule.same_plane_cos = static_cast<float>(std::cos(10.0 * 3.14159265 / 180.0));
  return rule;
}

std::vector<CandidatePlane> find(const Frame& frame, std::int32_t count,
                                 const CandidateRule& rule) {
  std::mt19937 rng(1);
  return find_candidate_planes(frame.labels, frame.xyz, count, rule, algo::RansacPlaneRule{}, rng);
}

void expect_table(const CandidatePlane& plane) {
  EXPECT_NEAR(plane.model.normal.y(), -1.0F, 1e-4F);  // towards the camera
  EXPECT_NEAR(plane.model.offset_m, 0.5F, 1e-4F);
}

void expect_wall(const CandidatePlane& plane) {
  EXPECT_NEAR(plane.model.normal.z(), -1.0F, 1e-4F);
  EXPECT_NEAR(plane.model.offset_m, 3.0F, 1e-4F);
  EXPECT_NEAR(plane.centroid_m.z(), 3.0F, 1e-4F);
}

TEST(CandidatePlanes, LargePatchesLargestFirstAndSmallOnesAreNoCandidates) {
  const Frame frame(2, 1, 3);  // the wall's patch has the lower id, the table is larger
  const auto planes = find(frame, 3, rule_for_the_frame());
  ASSERT_EQ(planes.size(), 2U);
  expect_table(planes[0]);
  EXPECT_EQ(planes[0].size_px, 60 * 60 - 50);
  expect_wall(planes[1]);
  EXPECT_EQ(planes[1].size_px, 40 * 60);
}

TEST(CandidatePlanes, OnlyTheLargestMaxCandidatesAreFitted) {
  const Frame frame(1, 2);
  CandidateRule rule = rule_for_the_frame();
  rule.max_candidates = 1;
  const auto planes = find(frame, 2, rule);
  ASSERT_EQ(planes.size(), 1U);
  expect_table(planes[0]);
}

TEST(CandidatePlanes, APatchThatHoldsTwoPlanesGivesOneCandidatePerPlane) {
  const Frame frame(1, 1);  // one patch over table and wall
  const auto planes = find(frame, 1, rule_for_the_frame());
  ASSERT_EQ(planes.size(), 2U);
  expect_table(planes[0]);
  EXPECT_EQ(planes[0].size_px, 60 * 60);
  EXPECT_NEAR(planes[0].centroid_m.y(), 0.5F, 1e-4F);  // its own points' centroid
  expect_wall(planes[1]);
  EXPECT_EQ(planes[1].size_px, 40 * 60);
}

TEST(CandidatePlanes, OnePlanePerPatchKeepsTheWholePatchOnTheFirstFit) {
  const Frame frame(1, 1);
  CandidateRule rule = rule_for_the_frame();
  rule.planes_per_patch = 1;
  const auto planes = find(frame, 1, rule);
  ASSERT_EQ(planes.size(), 1U);
  expect_table(planes[0]);
  EXPECT_EQ(planes[0].size_px, 100 * 60);
}

TEST(CandidatePlanes, ARemainderTooSmallForACandidateStaysWithTheFirstPlane) {
  const Frame frame(1, 1);
  CandidateRule rule = rule_for_the_frame();
  rule.min_px = 3000;  // the wall's 2400 pixels are not a candidate's worth
  const auto planes = find(frame, 1, rule);
  ASSERT_EQ(planes.size(), 1U);
  expect_table(planes[0]);
  EXPECT_EQ(planes[0].size_px, 100 * 60);
}

TEST(CandidatePlanes, NoPatchNoCandidate) {
  const Frame frame(0, 0);
  EXPECT_TRUE(find(frame, 0, rule_for_the_frame()).empty());
}

}  // namespace
}  // namespace facet::planes
