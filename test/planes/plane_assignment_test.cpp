// planes.support's last kernel: points within delta of a support plane join it, also out of
// their patch, except those of object faces: a box side's bottom band stays with the box, and a
// flat object's top just above the table stays with the object.
#include "planes/plane_assignment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <vector>

namespace facet::planes {
namespace {

constexpr std::int32_t kTable = 1;
constexpr std::int32_t kBoxSide = 2;
constexpr std::int32_t kBook = 3;

// 100 × 100 pixels, camera frame (y down). Rows 50..99: the table top, y = 0.5 m, patch 1,
// except a book 8 mm thick lying on it (rows 50..59, columns 0..19, patch 3) and a corner of
// table pixels that no patch holds (rows 90..99, columns 0..9). Rows 0..49, columns 40..59: the
// side of a box, z = 1 m, from 0.2 m above the table down to it (patch 2). The rest is invalid.
struct Frame {
  cv::Mat labels{100, 100, CV_32SC1, cv::Scalar(0)};
  cv::Mat xyz{100, 100, CV_32FC3, cv::Scalar::all(std::numeric_limits<float>::quiet_NaN())};
  std::int64_t table_px = 0;
  std::int64_t loose_px = 0;  // table pixels of no patch
  std::int64_t box_px = 0;
  std::int64_t book_px = 0;

  Frame() {
    for (int row = 0; row < 100; ++row) {
      for (int col = 0; col < 100; ++col) {
        const float x = -0.5F + static_cast<float>(col) / 99.0F;
        if (row >= 50) {
          const float z = 1.0F + static_cast<float>(row - 50) / 49.0F;
          if (row < 60 && col < 20) {
            xyz.at<cv::Vec3f>(row, col) = {x, 0.492F, z};
            labels.at<std::int32_t>(row, col) = kBook;
            ++book_px;
          } else if (row >= 90 && col < 10) {
            xyz.at<cv::Vec3f>(row, col) = {x, 0.5F, z};
            ++loose_px;
          } else {
            xyz.at<cv::Vec3f>(row, col) = {x, 0.5F, z};
            labels.at<std::int32_t>(row, col) = kTable;
            ++table_px;
          }
        } else if (col >= 40 && col < 60) {
          xyz.at<cv::Vec3f>(row, col) = {x, 0.3F + 0.2F * static_cast<float>(row) / 49.0F, 1.0F};
          labels.at<std::int32_t>(row, col) = kBoxSide;
          ++box_px;
        }
      }
    }
  }
};

const algo::Plane kTablePlane{Eigen::Vector3f(0.0F, -1.0F, 0.0F), 0.5F};

struct Result {
  PlaneAssignment assignment;
  cv::Mat plane_labels;
  cv::Mat left_labels;
};

Result assign(const Frame& frame, PlaneRole role) {
  Result out;
  out.assignment = assign_to_planes(frame.labels, 3, frame.xyz, {kTablePlane}, {role},
                                    role == PlaneRole::table ? 0 : -1, AssignmentRule{},
                                    out.plane_labels, out.left_labels);
  return out;
}

std::int64_t count(const cv::Mat& labels, std::int32_t value) {
  return cv::countNonZero(labels == value);
}

TEST(PlaneAssignment, TheTableTakesItsPointsAndThoseOfNoPatchButNoObjectFace) {
  const Frame frame;
  const Result result = assign(frame, PlaneRole::table);
  const PlaneAssignment& a = result.assignment;

  EXPECT_EQ(a.valid_px, frame.table_px + frame.loose_px + frame.box_px + frame.book_px);
  EXPECT_EQ(a.plane_px, frame.table_px + frame.loose_px);
  ASSERT_EQ(a.inliers.size(), 1U);
  EXPECT_EQ(a.inliers[0], frame.table_px + frame.loose_px);
  EXPECT_NEAR(a.rms_m[0], 0.0, 1e-6);
  EXPECT_EQ(count(result.plane_labels, 1), frame.table_px + frame.loose_px);

  // The box side's bottom band lies within delta of the table, but most of the side lies well
  // off it: the whole side stays with the box. The book's top lies within delta, 8 mm above:
  // raised, it stays with the book.
  EXPECT_EQ(count(result.left_labels, kBoxSide), frame.box_px);
  EXPECT_EQ(count(result.left_labels, kBook), frame.book_px);
  EXPECT_EQ(count(result.left_labels, kTable), 0);
  EXPECT_EQ(a.left_px[kBoxSide], frame.box_px);
  EXPECT_EQ(a.left_px[kBook], frame.book_px);
  EXPECT_EQ(a.left_px[kTable], 0);

  // The statistics per patch and plane that the table's outline is made from.
  ASSERT_EQ(a.patch_px.size(), 4U);
  EXPECT_EQ(a.patch_px[kTable], frame.table_px);
  EXPECT_EQ(a.patch_px[0], frame.loose_px);
  EXPECT_EQ(a.near_px[kTable], frame.table_px);
  EXPECT_EQ(a.near_px[kBook], frame.book_px);
  EXPECT_GT(a.near_px[kBoxSide], 0);
  EXPECT_LT(a.near_px[kBoxSide], frame.box_px / 4);
}

TEST(PlaneAssignment, OnlyHorizontalSupportsKeepRaisedPatchesOut) {
  // The same plane as a wall: the raised-top test is for the table and the floor only, so the
  // book's points, all within 2 delta, join it; the box side still keeps its band.
  const Frame frame;
  const Result result = assign(frame, PlaneRole::wall);
  EXPECT_EQ(result.assignment.plane_px, frame.table_px + frame.loose_px + frame.book_px);
  EXPECT_EQ(count(result.left_labels, kBook), 0);
  EXPECT_EQ(count(result.left_labels, kBoxSide), frame.box_px);
  // The RMS counts the book's points, 8 mm off, among the table's.
  const double book_share = static_cast<double>(frame.book_px) /
                            static_cast<double>(frame.table_px + frame.loose_px + frame.book_px);
  EXPECT_NEAR(result.assignment.rms_m[0], 0.008 * std::sqrt(book_share), 1e-5);
}

TEST(PlaneAssignment, WithoutPlanesEveryPatchKeepsItsPixels) {
  const Frame frame;
  cv::Mat plane_labels;
  cv::Mat left_labels;
  const PlaneAssignment a = assign_to_planes(frame.labels, 3, frame.xyz, {}, {}, -1,
                                             AssignmentRule{}, plane_labels, left_labels);
  EXPECT_EQ(a.plane_px, 0);
  EXPECT_EQ(cv::countNonZero(plane_labels), 0);
  EXPECT_EQ(cv::countNonZero(left_labels != frame.labels), 0);
}

}  // namespace
}  // namespace facet::planes
