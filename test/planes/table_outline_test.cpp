// The table's outline is the hull of the table's patches only: the pixels of other patches that
// happen to lie on the table's (infinite) plane do not stretch it.
#include "planes/table_outline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <vector>

namespace {

using facet::algo::Plane;
using facet::planes::table_outline;

// Camera frame, y down: the table plane y = 0.5 m (normal up, -y). The left half of the image is
// the table patch (id 1), x in [-0.5, 0.5] m, z in [1, 2] m. The right half is a far wall's patch
// (id 2) at z = 3 m, off the table's plane, except one row: where the wall crosses the table's
// height, 4 m wide. Both lie on the table's plane there, so both carry the table's plane id.
struct Frame {
  cv::Mat plane_labels{40, 100, CV_32SC1, cv::Scalar(0)};
  cv::Mat patch_labels{40, 100, CV_32SC1, cv::Scalar(0)};
  cv::Mat xyz{40, 100, CV_32FC3, cv::Scalar(0, 0, 0)};

  Frame() {
    for (int row = 0; row < 40; ++row) {
      for (int col = 0; col < 100; ++col) {
        auto& p = xyz.at<cv::Vec3f>(row, col);
        if (col < 50) {
          p = {-0.5F + static_cast<float>(col) / 49.0F, 0.5F,
               1.0F + static_cast<float>(row) / 39.0F};
          patch_labels.at<std::int32_t>(row, col) = 1;
          plane_labels.at<std::int32_t>(row, col) = 1;
        } else {
          const bool crossing = row == 39;
          p = {-2.0F + 4.0F * static_cast<float>(col - 50) / 49.0F,
               crossing ? 0.5F : -1.0F + static_cast<float>(row) / 39.0F, 3.0F};
          patch_labels.at<std::int32_t>(row, col) = 2;
          plane_labels.at<std::int32_t>(row, col) = crossing ? 1 : 0;
        }
      }
    }
  }
};

float max_abs_x(const std::vector<Eigen::Vector3d>& outline) {
  double widest = 0.0;
  for (const auto& vertex : outline)
    widest = std::max(widest, std::abs(vertex.x()));
  return static_cast<float>(widest);
}

TEST(TableOutline, OnlyTheTablesPatchesOutlineIt) {
  const Frame frame;
  const Plane table{Eigen::Vector3f(0.0F, -1.0F, 0.0F), 0.5F};
  const Eigen::Vector3f up(0.0F, -1.0F, 0.0F);
  const std::vector<char> table_ids = {0, 1};
  const std::vector<char> table_patch_only = {0, 1, 0};
  const auto outline = table_outline(frame.plane_labels, frame.patch_labels, table_patch_only,
                                     frame.xyz, table_ids, table, up, 1);
  ASSERT_GE(outline.size(), 3u);
  EXPECT_NEAR(max_abs_x(outline), 0.5F, 1e-4);
  // With the wall's patch taken for the table's, the row where it crosses the table's height
  // stretches the outline to the wall's width: what the share rule of planes.support prevents.
  const std::vector<char> both = {0, 1, 1};
  const auto stretched = table_outline(frame.plane_labels, frame.patch_labels, both, frame.xyz,
                                       table_ids, table, up, 1);
  EXPECT_NEAR(max_abs_x(stretched), 2.0F, 1e-4);
}

}  // namespace
