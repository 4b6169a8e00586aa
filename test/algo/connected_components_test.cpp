// facet::algo::ComponentLabeler: components of one value, numbered in raster order of their
// first pixel, with a size floor; the same partition as OpenCV's labelling on random images.
#include "facet/algo/connected_components.hpp"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace facet::algo {
namespace {

cv::Mat from_rows(std::initializer_list<std::initializer_list<int>> rows) {
  cv::Mat image(static_cast<int>(rows.size()), static_cast<int>(rows.begin()->size()), CV_8UC1);
  int r = 0;
  for (const auto& row : rows) {
    int c = 0;
    for (const int value : row)
      image.at<std::uint8_t>(r, c++) = static_cast<std::uint8_t>(value);
    ++r;
  }
  return image;
}

TEST(ComponentLabeler, OnlyPixelsOfTheValueInRasterOrderOfTheirFirstPixel) {
  const cv::Mat image = from_rows({{0, 2, 2, 0, 1, 1},  //
                                   {0, 0, 2, 0, 0, 2},  //
                                   {2, 0, 0, 0, 2, 2},  //
                                   {2, 2, 0, 1, 0, 0}});
  ComponentLabeler labeler;
  cv::Mat labels(image.size(), CV_32SC1, cv::Scalar(-7));
  const Components found = labeler.label(image, 2, 8, 0, labels);
  EXPECT_EQ(found.count, 3);
  EXPECT_EQ(found.labelled_px, 9);
  const cv::Mat expected = from_rows({{0, 1, 1, 0, 0, 0},  //
                                      {0, 0, 1, 0, 0, 2},  //
                                      {3, 0, 0, 0, 2, 2},  //
                                      {3, 3, 0, 0, 0, 0}});
  cv::Mat expected_32;
  expected.convertTo(expected_32, CV_32S);
  EXPECT_EQ(cv::countNonZero(labels != expected_32), 0);
  EXPECT_EQ(labeler.size_px(1), 3);
  EXPECT_EQ(labeler.size_px(2), 3);
  EXPECT_EQ(labeler.size_px(3), 3);
}

TEST(ComponentLabeler, DiagonalNeighboursJoinOnlyWithEightConnectivity) {
  const cv::Mat image = from_rows({{9, 0, 0},  //
                                   {0, 9, 0},  //
                                   {0, 0, 9}});
  ComponentLabeler labeler;
  cv::Mat labels(image.size(), CV_32SC1);
  EXPECT_EQ(labeler.label(image, 9, 8, 0, labels).count, 1);
  EXPECT_EQ(labeler.label(image, 9, 4, 0, labels).count, 3);
}

TEST(ComponentLabeler, ComponentsUnderTheSizeFloorStayZeroAndTakeNoId) {
  const cv::Mat image = from_rows({{1, 0, 1, 1},  //
                                   {0, 0, 1, 1}});
  ComponentLabeler labeler;
  cv::Mat labels(image.size(), CV_32SC1);
  const Components found = labeler.label(image, 1, 8, 2, labels);
  EXPECT_EQ(found.count, 1);
  EXPECT_EQ(labels.at<std::int32_t>(0, 0), 0);
  EXPECT_EQ(labels.at<std::int32_t>(1, 3), 1);
  EXPECT_EQ(labeler.size_px(1), 4);
}

// The runs of the labelled components, row by row, and a renumbering that drops one component
// and keeps the others' order: pixels of no component are left as they were.
TEST(ComponentLabeler, VisitsTheRunsAndRenumbersWithoutTouchingOtherPixels) {
  const cv::Mat image = from_rows({{4, 4, 0, 4},  //
                                   {0, 0, 0, 4},  //
                                   {4, 0, 4, 4}});
  ComponentLabeler labeler;
  cv::Mat labels(image.size(), CV_32SC1);
  ASSERT_EQ(labeler.label(image, 4, 4, 0, labels).count, 3);
  std::vector<std::array<int, 4>> runs;
  labeler.for_each_run([&](std::int32_t id, int row, int begin, int end) {
    runs.push_back({id, row, begin, end});
  });
  const std::vector<std::array<int, 4>> expected_runs{
      {1, 0, 0, 2}, {2, 0, 3, 4}, {2, 1, 3, 4}, {3, 2, 0, 1}, {2, 2, 2, 4}};
  EXPECT_EQ(runs, expected_runs);

  labels.at<std::int32_t>(1, 1) = -5;  // not a component's pixel: relabel leaves it
  labeler.relabel({0, 1, 0, 2}, labels);
  const cv::Mat expected = from_rows({{1, 1, 0, 0},  //
                                      {0, 0, 0, 0},  //
                                      {2, 0, 0, 0}});
  cv::Mat expected_32;
  expected.convertTo(expected_32, CV_32S);
  expected_32.at<std::int32_t>(1, 1) = -5;
  EXPECT_EQ(cv::countNonZero(labels != expected_32), 0);
  EXPECT_EQ(labeler.size_px(1), 2);
  EXPECT_EQ(labeler.size_px(2), 1);
  runs.clear();
  labeler.for_each_run([&](std::int32_t id, int row, int begin, int end) {
    runs.push_back({id, row, begin, end});
  });
  EXPECT_EQ(runs, (std::vector<std::array<int, 4>>{{1, 0, 0, 2}, {2, 2, 0, 1}}));

  EXPECT_THROW(labeler.relabel({0, 1}, labels), std::invalid_argument);     // too few
  EXPECT_THROW(labeler.relabel({0, 2, 1}, labels), std::invalid_argument);  // out of order
  EXPECT_THROW(labeler.relabel({0, 0, 2}, labels), std::invalid_argument);  // a gap
}

// A view into a larger buffer is written, and nothing around it.
TEST(ComponentLabeler, WritesIntoAViewOnly) {
  cv::Mat buffer(6, 6, CV_32SC1, cv::Scalar(-1));
  cv::Mat view = buffer(cv::Rect(1, 1, 3, 2));
  const cv::Mat image = from_rows({{5, 5, 0},  //
                                   {0, 0, 5}});
  ComponentLabeler labeler;
  EXPECT_EQ(labeler.label(image, 5, 8, 0, view).count, 1);
  EXPECT_EQ(buffer.at<std::int32_t>(1, 1), 1);
  EXPECT_EQ(buffer.at<std::int32_t>(1, 3), 0);
  EXPECT_EQ(buffer.at<std::int32_t>(2, 3), 1);
  EXPECT_EQ(buffer.at<std::int32_t>(0, 0), -1);
  EXPECT_EQ(buffer.at<std::int32_t>(3, 4), -1);
}

// The values 0, 1, 2 and 255 among pixels of the others (the 8-pixel bit test must pick exactly
// the value asked for, top bit included), and both connectivities: the same partition of the
// pixels as cv::connectedComponents.
TEST(ComponentLabeler, SamePartitionAsOpenCvOnRandomImages) {
  cv::RNG rng(5);
  ComponentLabeler labeler;
  for (int trial = 0; trial < 40; ++trial) {
    cv::Mat image(37 + trial, 61, CV_8UC1);
    rng.fill(image, cv::RNG::UNIFORM, 0, 4);
    const auto value = static_cast<std::uint8_t>(trial % 4 == 3 ? 255 : trial % 4);
    if (value == 255) image.setTo(255, image == 3);
    const int connectivity = trial % 2 == 0 ? 8 : 4;
    cv::Mat labels(image.size(), CV_32SC1);
    const Components found = labeler.label(image, value, connectivity, 0, labels);
    cv::Mat reference;
    const int reference_count =
        cv::connectedComponents(image == value, reference, connectivity, CV_32S);
    ASSERT_EQ(found.count, reference_count - 1) << "trial " << trial;
    std::map<int, int> ours_to_theirs;
    std::map<int, int> theirs_to_ours;
    for (int r = 0; r < image.rows; ++r) {
      for (int c = 0; c < image.cols; ++c) {
        const int ours = labels.at<std::int32_t>(r, c);
        const int theirs = reference.at<std::int32_t>(r, c);
        ASSERT_EQ(ours == 0, theirs == 0);
        if (ours == 0) continue;
        ASSERT_EQ(ours_to_theirs.emplace(ours, theirs).first->second, theirs);
        ASSERT_EQ(theirs_to_ours.emplace(theirs, ours).first->second, ours);
      }
    }
  }
}

TEST(ComponentLabeler, RefusesWrongTypesSizesAndConnectivities) {
  ComponentLabeler labeler;
  cv::Mat labels(2, 2, CV_32SC1);
  EXPECT_THROW(labeler.label(cv::Mat(2, 2, CV_16UC1), 1, 8, 0, labels), std::invalid_argument);
  EXPECT_THROW(labeler.label(cv::Mat(3, 2, CV_8UC1), 1, 8, 0, labels), std::invalid_argument);
  EXPECT_THROW(labeler.label(cv::Mat(2, 2, CV_8UC1), 1, 6, 0, labels), std::invalid_argument);
}

}  // namespace
}  // namespace facet::algo
