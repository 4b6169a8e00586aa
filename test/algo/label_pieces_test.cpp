// facet::algo::LabelPieces: one label per connected piece of the labels asked for.
#include "facet/algo/label_pieces.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <opencv2/core.hpp>
#include <vector>

namespace facet::algo {
namespace {

// A flat surface 1 m away with 1 mm between neighbouring pixels.
cv::Mat flat_points(int rows, int cols) {
  cv::Mat points(rows, cols, CV_32FC3);
  for (int v = 0; v < rows; ++v) {
    for (int u = 0; u < cols; ++u)
      points.at<cv::Vec3f>(v, u) =
          cv::Vec3f(0.001F * static_cast<float>(u), 0.001F * static_cast<float>(v), 1.0F);
  }
  return points;
}

const NeighbourGate kGate(0.01F, 0.0F);

TEST(LabelPieces, TheLargestPieceKeepsItsIdTheOthersGetNewOnes) {
  cv::Mat labels = cv::Mat::zeros(10, 20, CV_32SC1);
  labels(cv::Rect(0, 0, 3, 3)).setTo(1);   // 9 px, first in raster order
  labels(cv::Rect(10, 2, 5, 5)).setTo(1);  // 25 px: the largest
  labels(cv::Rect(0, 8, 2, 2)).setTo(1);   // 4 px
  labels(cv::Rect(5, 5, 2, 2)).setTo(2);   // not asked for: stays as it is
  labels(cv::Rect(17, 8, 2, 2)).setTo(2);
  LabelPieces pieces;
  const std::int32_t count = pieces.split(labels, 2, {0, 1, 0}, flat_points(10, 20), kGate);
  EXPECT_EQ(count, 4);
  EXPECT_EQ(labels.at<int>(4, 12), 1);
  EXPECT_EQ(labels.at<int>(1, 1), 3);  // raster order of the new pieces
  EXPECT_EQ(labels.at<int>(9, 1), 4);
  EXPECT_EQ(labels.at<int>(5, 5), 2);
  EXPECT_EQ(labels.at<int>(8, 17), 2);
  EXPECT_EQ(cv::countNonZero(labels == 1), 25);
  EXPECT_EQ(cv::countNonZero(labels == 0), 200 - 9 - 25 - 4 - 8);
}

TEST(LabelPieces, DiagonalNeighboursAreOnePiece) {
  cv::Mat labels = cv::Mat::zeros(4, 4, CV_32SC1);
  for (int i = 0; i < 4; ++i)
    labels.at<int>(i, 3 - i) = 1;  // an anti-diagonal line
  LabelPieces pieces;
  EXPECT_EQ(pieces.split(labels, 1, {0, 1}, flat_points(4, 4), kGate), 1);
  EXPECT_EQ(cv::countNonZero(labels == 1), 4);
}

TEST(LabelPieces, ADepthStepSplitsAPieceThatTouchesInTheImage) {
  cv::Mat labels(6, 8, CV_32SC1, cv::Scalar(1));
  cv::Mat points = flat_points(6, 8);
  // The right half 5 cm nearer: the top of an object seen against the table behind it.
  for (int v = 0; v < 6; ++v) {
    for (int u = 4; u < 8; ++u)
      points.at<cv::Vec3f>(v, u)[2] = 0.95F;
  }
  LabelPieces pieces;
  EXPECT_EQ(pieces.split(labels, 1, {0, 1}, points, kGate), 2);
  EXPECT_EQ(labels.at<int>(0, 0), 1);  // equal sizes: the first in raster order keeps the id
  EXPECT_EQ(labels.at<int>(0, 4), 2);
  EXPECT_EQ(cv::countNonZero(labels == 2), 24);
}

TEST(LabelPieces, APixelWithoutAPointIsAPieceOfItsOwn) {
  cv::Mat labels(3, 3, CV_32SC1, cv::Scalar(1));
  cv::Mat points = flat_points(3, 3);
  points.at<cv::Vec3f>(1, 1)[2] = std::numeric_limits<float>::quiet_NaN();
  LabelPieces pieces;
  EXPECT_EQ(pieces.split(labels, 1, {0, 1}, points, kGate), 2);
  EXPECT_EQ(labels.at<int>(1, 1), 2);
  EXPECT_EQ(cv::countNonZero(labels == 1), 8);
}

TEST(LabelPieces, NothingAskedForChangesNothing) {
  cv::Mat labels = cv::Mat::zeros(5, 5, CV_32SC1);
  labels(cv::Rect(0, 0, 2, 2)).setTo(1);
  labels(cv::Rect(3, 3, 2, 2)).setTo(1);
  const cv::Mat before = labels.clone();
  LabelPieces pieces;
  EXPECT_EQ(pieces.split(labels, 1, {0, 0}, flat_points(5, 5), kGate), 1);
  EXPECT_EQ(cv::countNonZero(labels != before), 0);
}

TEST(LabelPieces, RejectsImagesOfTheWrongKind) {
  cv::Mat labels = cv::Mat::zeros(5, 5, CV_16UC1);
  LabelPieces pieces;
  EXPECT_THROW(pieces.split(labels, 1, {0, 1}, flat_points(5, 5), kGate), std::invalid_argument);
  cv::Mat small = cv::Mat::zeros(4, 5, CV_32SC1);
  EXPECT_THROW(pieces.split(small, 1, {0, 1}, flat_points(5, 5), kGate), std::invalid_argument);
}

}  // namespace
}  // namespace facet::algo
