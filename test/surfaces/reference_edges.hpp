#pragma once
// The edge score written the plain way, in double precision: 8 directions, R offsets each, no
// shared products. The optimised stages must agree with it. skip_invalid: a direction that meets
// a pixel without a normal is left out (edges' invalid_neighbours: skip) instead of making the
// whole pixel score 0.

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

namespace facet::test {

inline cv::Mat reference_edge_score(const cv::Mat& normals, int reach_px, bool take_min,
                                    bool skip_invalid = false) {
  static constexpr int kSteps[8][2] = {{0, -1}, {1, -1}, {1, 0},  {1, 1},
                                       {0, 1},  {-1, 1}, {-1, 0}, {-1, -1}};
  cv::Mat score = cv::Mat::zeros(normals.size(), CV_64FC1);
  for (int y = reach_px; y + reach_px < normals.rows; ++y) {
    for (int x = reach_px; x + reach_px < normals.cols; ++x) {
      const cv::Vec3d n = normals.at<cv::Vec3f>(y, x);
      double smallest = 2.0;
      double total = 0.0;
      int directions = 0;
      bool valid = std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]);
      for (const auto& step : kSteps) {
        double sum = 0.0;
        bool direction_valid = true;
        for (int k = 1; k <= reach_px; ++k) {
          const cv::Vec3d m = normals.at<cv::Vec3f>(y + k * step[1], x + k * step[0]);
          if (!(std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2])))
            direction_valid = false;
          sum += std::abs(n.dot(m));
        }
        if (!direction_valid) {
          if (!skip_invalid) valid = false;
          continue;
        }
        const double mean = sum / reach_px;
        smallest = std::min(smallest, mean);
        total += mean;
        ++directions;
      }
      if (valid && directions > 0)
        score.at<double>(y, x) = take_min ? smallest : total / directions;
    }
  }
  return score;
}

}  // namespace facet::test
