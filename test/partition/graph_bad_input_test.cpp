// partition.graph on bad input: a single patch, hundreds of tiny patches, patches without a
// usable plane, a patch that touches every other. Empty frames and the other degenerate cases
// are in robustness_test.cpp, which runs every partition stage.

#include <gtest/gtest.h>

#include "graph_scenes.hpp"
#include "partition/graph_stage.hpp"
#include "test_scenes.hpp"

namespace facet::test {
namespace {

using partition::PartitionGraph;

// A flat square of points 1 m in front of the camera (a wall patch), `side_px` wide, at the
// image centre; blob 1, no patches yet.
PartitionInput flat_square(int side_px) {
  PartitionInput input;
  const CameraIntrinsics camera = kinect_camera();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  input.points.camera = camera;
  input.points.points = cv::Mat(camera.height, camera.width, CV_32FC3, cv::Scalar(nan, nan, nan));
  cv::Mat blobs = cv::Mat::zeros(camera.height, camera.width, CV_32SC1);
  const cv::Rect square((camera.width - side_px) / 2, (camera.height - side_px) / 2, side_px,
                        side_px);
  for (int v = square.y; v < square.y + square.height; ++v) {
    for (int u = square.x; u < square.x + square.width; ++u) {
      input.points.points.at<cv::Vec3f>(v, u) =
          cv::Vec3f(static_cast<float>((u - camera.cx) / camera.fx),
                    static_cast<float>((v - camera.cy) / camera.fy), 1.0F);
      blobs.at<std::int32_t>(v, u) = 1;
    }
  }
  input.blobs = label_image(blobs);
  input.patches = label_image(cv::Mat::zeros(camera.height, camera.width, CV_32SC1));
  return input;
}

std::int32_t labelled_px(const LabelImage& objects) {
  return cv::countNonZero(objects.labels > 0);
}

TEST(PartitionGraphBadInput, BlobOfOnePatchIsOneObject) {
  PartitionInput input = flat_square(200);
  input.patches = label_image(input.blobs.labels.clone());
  input.adjacency = contacts_of(input.patches.labels);
  std::vector<Metric> metrics;
  const LabelImage objects = run_partition<PartitionGraph>(input, {}, &metrics);
  EXPECT_EQ(objects.count, 1);
  EXPECT_EQ(labelled_px(objects), 200 * 200);
  EXPECT_EQ(metric_value(metrics, "nodes"), 1.0);
}

TEST(PartitionGraphBadInput, FiveHundredTinyPatches) {
  // A grid of 500 patches of 4 x 4 pixels, all in one blob and each touching its neighbours:
  // too small to be nodes by default (the blob is one object), and 500 nodes when allowed.
  PartitionInput input = flat_square(200);
  cv::Mat patches = cv::Mat::zeros(input.blobs.labels.size(), CV_32SC1);
  const int u0 = (patches.cols - 200) / 2;
  const int v0 = (patches.rows - 200) / 2;
  for (int k = 0; k < 500; ++k) {
    patches(cv::Rect(u0 + 4 * (k % 50), v0 + 4 * (k / 50), 4, 4)).setTo(k + 1);
  }
  input.patches = label_image(patches);
  input.adjacency = contacts_of(patches);
  const LabelImage objects = run_partition<PartitionGraph>(input);
  EXPECT_EQ(objects.count, 1);
  EXPECT_EQ(labelled_px(objects), 200 * 200);

  std::vector<Metric> metrics;
  const LabelImage fine = run_partition<PartitionGraph>(input, {{"min_patch_px", 16}}, &metrics);
  EXPECT_EQ(metric_value(metrics, "nodes"), 500.0);
  // One flat wall: no convex junction (normals equal), no curved patch, no other blob.
  EXPECT_EQ(metric_value(metrics, "convex_edges"), 0.0);
  EXPECT_EQ(fine.count, 500);
  EXPECT_EQ(labelled_px(fine), 200 * 200);
}

TEST(PartitionGraphBadInput, PatchesWithoutAUsablePlane) {
  // Patch 1: no valid point at all; patch 2: a one-pixel-wide line (collinear points, no plane);
  // patch 3: a proper square. Every blob pixel still gets an object.
  PartitionInput input = flat_square(200);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cv::Mat patches = cv::Mat::zeros(input.blobs.labels.size(), CV_32SC1);
  const int u0 = (patches.cols - 200) / 2;
  const int v0 = (patches.rows - 200) / 2;
  const cv::Rect no_points(u0, v0, 200, 40);
  patches(no_points).setTo(1);
  input.points.points(no_points).setTo(cv::Scalar(nan, nan, nan));
  patches(cv::Rect(u0, v0 + 60, 200, 1)).setTo(2);
  patches(cv::Rect(u0, v0 + 100, 100, 100)).setTo(3);
  input.patches = label_image(patches);
  input.adjacency = contacts_of(patches);
  std::vector<Metric> metrics;
  const LabelImage objects = run_partition<PartitionGraph>(input, {}, &metrics);
  EXPECT_EQ(metric_value(metrics, "nodes"), 1.0);  // only patch 3
  EXPECT_EQ(objects.count, 1);
  EXPECT_EQ(labelled_px(objects), 200 * 200);
}

TEST(PartitionGraphBadInput, PatchTouchingEveryOther) {
  // A frame patch around a grid of 36 patches on a wavy surface (every one curved, each touching
  // the frame): many candidate pairs for every feature at once.
  PartitionInput input = flat_square(240);
  cv::Mat patches = cv::Mat::zeros(input.blobs.labels.size(), CV_32SC1);
  const int u0 = (patches.cols - 240) / 2;
  const int v0 = (patches.rows - 240) / 2;
  patches(cv::Rect(u0, v0, 240, 240)).setTo(1);
  for (int k = 0; k < 36; ++k) {
    patches(cv::Rect(u0 + 12 + 36 * (k % 6), v0 + 12 + 36 * (k / 6), 30, 30)).setTo(k + 2);
  }
  for (int v = v0; v < v0 + 240; ++v) {
    for (int u = u0; u < u0 + 240; ++u) {
      cv::Vec3f& p = input.points.points.at<cv::Vec3f>(v, u);
      const float z = 1.0F + 0.02F * std::sin(0.2F * static_cast<float>(u)) *
                                 std::cos(0.2F * static_cast<float>(v));
      p = cv::Vec3f(p[0] * z, p[1] * z, z);
    }
  }
  input.patches = label_image(patches);
  input.adjacency = contacts_of(patches);
  ASSERT_EQ(input.adjacency.pairs.size(), 36U);  // the frame and each square, nothing else
  std::vector<Metric> metrics;
  const LabelImage objects = run_partition<PartitionGraph>(input, {}, &metrics);
  EXPECT_EQ(metric_value(metrics, "nodes"), 37.0);
  EXPECT_GE(objects.count, 1);
  EXPECT_LE(objects.count, 37);
  EXPECT_EQ(labelled_px(objects), 240 * 240);
}

TEST(PartitionGraphBadInput, ManyBlobsOfCoplanarPatches) {
  // 400 small blobs of one plane with nothing between them (the background shows through): many
  // coplanar candidates, none occluded, none joined.
  PartitionInput input = flat_square(400);
  cv::Mat blobs = cv::Mat::zeros(input.blobs.labels.size(), CV_32SC1);
  const int u0 = (blobs.cols - 400) / 2;
  const int v0 = (blobs.rows - 400) / 2;
  for (int k = 0; k < 400; ++k) {
    blobs(cv::Rect(u0 + 20 * (k % 20), v0 + 20 * (k / 20), 15, 15)).setTo(k + 1);
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  input.points.points.setTo(cv::Scalar(nan, nan, nan), blobs == 0);
  input.blobs = label_image(blobs);
  input.patches = label_image(blobs.clone());
  input.adjacency = contacts_of(blobs);
  std::vector<Metric> metrics;
  const LabelImage objects =
      run_partition<PartitionGraph>(input, {{"min_patch_px", 100}}, &metrics);
  EXPECT_EQ(metric_value(metrics, "nodes"), 400.0);
  EXPECT_EQ(metric_value(metrics, "coplanar_edges"), 0.0);
  EXPECT_EQ(objects.count, 400);
}

}  // namespace
}  // namespace facet::test
