// fill_blob_gaps against its definition: a breadth-first growth from every labelled blob pixel in
// raster order, then one new object per connected part that no label reached. The stage's version
// starts only from the labelled pixels beside a gap; the result must be the same, pixel for pixel.
#include "partition/object_labels.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

namespace facet::partition {
namespace {

void grow_from(cv::Mat& objects, const cv::Mat& blobs, std::vector<std::int32_t> queue) {
  const int width = objects.cols;
  auto* labels = objects.ptr<std::int32_t>();
  const auto* blob = blobs.ptr<std::int32_t>();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t i = queue[head];
    const int u = i % width;
    const int v = i / width;
    for (int dv = -1; dv <= 1; ++dv) {
      for (int du = -1; du <= 1; ++du) {
        const int nu = u + du;
        const int nv = v + dv;
        if (nu < 0 || nv < 0 || nu >= width || nv >= objects.rows) continue;
        const std::int32_t j = nv * width + nu;
        if (labels[j] != 0 || blob[j] != blob[i]) continue;
        labels[j] = labels[i];
        queue.push_back(j);
      }
    }
  }
}

void fill_by_definition(cv::Mat& objects, const cv::Mat& blobs, std::int32_t next_id) {
  auto* labels = objects.ptr<std::int32_t>();
  const auto* blob = blobs.ptr<std::int32_t>();
  const auto n = static_cast<std::int32_t>(objects.total());
  std::vector<std::int32_t> labelled;
  for (std::int32_t i = 0; i < n; ++i) {
    if (blob[i] > 0 && labels[i] != 0) labelled.push_back(i);
  }
  grow_from(objects, blobs, labelled);
  for (std::int32_t i = 0; i < n; ++i) {
    if (blob[i] <= 0 || labels[i] != 0) continue;
    labels[i] = next_id++;
    grow_from(objects, blobs, {i});
  }
}

// Blobs of random rectangles over a background, objects labelled on a random share of their
// pixels: gaps of every size, some parts of blobs with no label at all.
struct RandomScene {
  cv::Mat blobs;
  cv::Mat objects;
};

RandomScene random_scene(std::uint32_t seed, double labelled_share) {
  std::mt19937 rng(seed);
  RandomScene s;
  s.blobs = cv::Mat::zeros(60, 90, CV_32SC1);
  std::uniform_int_distribution<int> col(0, 80);
  std::uniform_int_distribution<int> row(0, 50);
  std::uniform_int_distribution<int> side(3, 30);
  for (std::int32_t id = 1; id <= 6; ++id) {
    const cv::Rect box(col(rng), row(rng), side(rng), side(rng));
    s.blobs(box & cv::Rect(0, 0, s.blobs.cols, s.blobs.rows)).setTo(id);
  }
  s.objects = cv::Mat::zeros(s.blobs.size(), CV_32SC1);
  std::bernoulli_distribution labelled(labelled_share);
  std::uniform_int_distribution<int> object(1, 9);
  for (int v = 0; v < s.blobs.rows; ++v) {
    for (int u = 0; u < s.blobs.cols; ++u) {
      if (s.blobs.at<std::int32_t>(v, u) > 0 && labelled(rng))
        s.objects.at<std::int32_t>(v, u) = object(rng);
    }
  }
  return s;
}

TEST(FillBlobGaps, AgreesWithGrowingFromEveryLabelledPixel) {
  for (const double share : {0.0, 0.02, 0.3, 0.9, 1.0}) {
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
      const RandomScene s = random_scene(seed, share);
      cv::Mat expected = s.objects.clone();
      fill_by_definition(expected, s.blobs, 10);
      cv::Mat objects = s.objects.clone();
      fill_blob_gaps(objects, s.blobs, 10);
      EXPECT_EQ(cv::countNonZero(objects != expected), 0) << "share " << share << " seed " << seed;
      // Every blob pixel ends up in an object, no pixel outside the blobs does.
      EXPECT_EQ(cv::countNonZero((objects == 0) & (s.blobs > 0)), 0);
      EXPECT_EQ(cv::countNonZero((objects != 0) & (s.blobs <= 0)), 0);
    }
  }
}

TEST(FillBlobGaps, APartNoLabelReachesIsAnObjectOfItsOwn) {
  cv::Mat blobs = cv::Mat::zeros(10, 20, CV_32SC1);
  blobs.colRange(0, 8).setTo(1);
  blobs.colRange(12, 20).setTo(1);  // the same blob id, but not connected
  cv::Mat objects = cv::Mat::zeros(blobs.size(), CV_32SC1);
  objects.at<std::int32_t>(5, 2) = 4;
  fill_blob_gaps(objects, blobs, 7);
  EXPECT_EQ(cv::countNonZero(objects.colRange(0, 8) != 4), 0);
  EXPECT_EQ(cv::countNonZero(objects.colRange(12, 20) != 7), 0);
  EXPECT_EQ(cv::countNonZero(objects.colRange(8, 12)), 0);
}

}  // namespace
}  // namespace facet::partition
