// What io.view draws, without a window: each picture from known inputs.

#include "view/view_render.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>

#include "io/label_palette.hpp"

namespace facet::view {
namespace {

cv::Vec3b bgr(const io::Rgb& c) {
  return {c.b, c.g, c.r};
}

// A 4x3 depth image: rows at 800, 1000 and 1200 mm, pixel (0, 0) without measurement.
DepthImage three_depths() {
  DepthImage image;
  image.depth = cv::Mat(3, 4, CV_16UC1);
  for (int y = 0; y < 3; ++y)
    image.depth.row(y).setTo(800 + 200 * y);
  image.depth.at<std::uint16_t>(0, 0) = 0;
  return image;
}

TEST(ViewRender, DepthIsGreyNearBrightFarDarkAndNoMeasurementBlack) {
  const cv::Mat image = render_depth(three_depths().depth);
  ASSERT_EQ(image.type(), CV_8UC3);
  ASSERT_EQ(image.size(), cv::Size(4, 3));
  const cv::Vec3b none = image.at<cv::Vec3b>(0, 0);
  const cv::Vec3b near = image.at<cv::Vec3b>(0, 1);
  const cv::Vec3b far = image.at<cv::Vec3b>(2, 1);
  EXPECT_EQ(none, cv::Vec3b(0, 0, 0));
  EXPECT_EQ(near[0], near[1]);  // grey
  EXPECT_EQ(near[1], near[2]);
  EXPECT_GT(near[0], far[0]);
  EXPECT_GT(far[0], 0);  // the farthest valid depth is still not "no measurement"
}

TEST(ViewRender, NormalsFacingTheCameraAreBlueAndSidewaysOnesCarryTheirDirection) {
  cv::Mat normals(1, 4, CV_32FC3);
  normals.at<cv::Vec3f>(0, 0) = {0.0F, 0.0F, -1.0F};  // facing the camera
  normals.at<cv::Vec3f>(0, 1) = {1.0F, 0.0F, 0.0F};   // facing right
  normals.at<cv::Vec3f>(0, 2) = {0.0F, -1.0F, 0.0F};  // facing up (y points down)
  const float nan = std::numeric_limits<float>::quiet_NaN();
  normals.at<cv::Vec3f>(0, 3) = {nan, nan, nan};
  const cv::Mat image = render_normals(normals);
  EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(255, 128, 128));  // B, G, R
  EXPECT_EQ(image.at<cv::Vec3b>(0, 1), cv::Vec3b(128, 128, 255));
  EXPECT_EQ(image.at<cv::Vec3b>(0, 2), cv::Vec3b(128, 0, 128));
  EXPECT_EQ(image.at<cv::Vec3b>(0, 3), cv::Vec3b(0, 0, 0));
}

TEST(ViewRender, EdgesShowTheScoreInGreyEdgePixelsInMagentaAndHolesBlack) {
  cv::Mat score(1, 4, CV_32FC1);
  score.at<float>(0, 0) = 1.0F;
  score.at<float>(0, 1) = 0.5F;
  score.at<float>(0, 2) = 0.9F;
  score.at<float>(0, 3) = std::numeric_limits<float>::quiet_NaN();
  cv::Mat mask = cv::Mat::zeros(1, 4, CV_8UC1);
  mask.at<std::uint8_t>(0, 2) = 255;
  mask.at<std::uint8_t>(0, 3) = 255;  // no surface: an edge for grow.surfaces, a hole to look at
  const cv::Mat image = render_edges(score, mask);
  EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(image.at<cv::Vec3b>(0, 1), cv::Vec3b(128, 128, 128));
  EXPECT_EQ(image.at<cv::Vec3b>(0, 2), cv::Vec3b(255, 0, 255));
  EXPECT_EQ(image.at<cv::Vec3b>(0, 3), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(render_edges(cv::Mat(), mask).at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
}

TEST(ViewRender, LabelsWithoutDepthHaveTheOverlayColoursOnBlack) {
  cv::Mat labels = cv::Mat::zeros(2, 2, CV_32SC1);
  labels.at<std::int32_t>(0, 1) = 1;
  labels.at<std::int32_t>(1, 0) = 7;
  const cv::Mat image = render_labels(labels, cv::Mat());
  EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(image.at<cv::Vec3b>(0, 1), bgr(io::label_colour(1)));
  EXPECT_EQ(image.at<cv::Vec3b>(1, 0), bgr(io::label_colour(7)));
}

TEST(ViewRender, LabelsOverDepthKeepTheGreyOfTheBackground) {
  const DepthImage depth = three_depths();
  cv::Mat labels = cv::Mat::zeros(3, 4, CV_32SC1);
  labels(cv::Rect(2, 0, 2, 3)).setTo(3);  // the right half is segment 3
  const cv::Mat image = render_labels(labels, depth.depth);
  const cv::Mat grey = render_depth(depth.depth);
  EXPECT_EQ(image.at<cv::Vec3b>(1, 0), grey.at<cv::Vec3b>(1, 0));  // background stays grey
  EXPECT_NE(image.at<cv::Vec3b>(1, 3), grey.at<cv::Vec3b>(1, 3));  // the segment is coloured
}

TEST(ViewRender, AllTilesTheConnectedInputsTwoPerRow) {
  DepthImage depth;
  depth.depth = cv::Mat(60, 80, CV_16UC1, cv::Scalar(1000));
  NormalImage normals;
  normals.normals = cv::Mat(60, 80, CV_32FC3, cv::Scalar(0.0, 0.0, -1.0));
  LabelImage labels;
  labels.labels = cv::Mat::ones(60, 80, CV_32SC1);
  ViewInputs inputs;
  inputs.depth = &depth;
  inputs.normals = &normals;
  inputs.labels = &labels;
  const cv::Mat all = render_view(inputs, Show::all, 1.0);
  EXPECT_EQ(all.size(), cv::Size(160, 120));                   // 3 tiles: 2 columns, 2 rows
  EXPECT_EQ(all.at<cv::Vec3b>(119, 159), cv::Vec3b(0, 0, 0));  // the empty fourth cell
  // Each tile is its picture (away from the caption in its top left corner): depth top left,
  // normals top right, labels bottom left.
  EXPECT_EQ(all.at<cv::Vec3b>(50, 70), render_depth(depth.depth).at<cv::Vec3b>(50, 70));
  EXPECT_EQ(all.at<cv::Vec3b>(50, 150), cv::Vec3b(255, 128, 128));
  EXPECT_EQ(all.at<cv::Vec3b>(110, 70),
            render_labels(labels.labels, depth.depth).at<cv::Vec3b>(50, 70));
  // The captions are drawn: the top left corner of the normals tile is no longer blue.
  EXPECT_NE(all.at<cv::Vec3b>(2, 82), cv::Vec3b(255, 128, 128));
}

TEST(ViewRender, APictureWhoseInputIsMissingIsEmptyAndScaleZooms) {
  const DepthImage depth = three_depths();
  ViewInputs inputs;
  inputs.depth = &depth;
  EXPECT_TRUE(render_view(inputs, Show::labels, 1.0).empty());
  EXPECT_TRUE(render_view(inputs, Show::normals, 1.0).empty());
  EXPECT_EQ(render_view(inputs, Show::depth, 2.0).size(), cv::Size(8, 6));
  EXPECT_EQ(render_view(ViewInputs{}, Show::all, 1.0).empty(), true);
}

}  // namespace
}  // namespace facet::view
