#pragma once
// Region growing, assignment and adjacency written the plain way: a breadth-first flood fill
// from each unvisited pixel in raster order, assignment rounds that each look at every pixel of
// the image, and all 8 neighbours of every pixel for the contacts. The grow.surfaces stage must
// agree.

#include <cstdint>
#include <cstdlib>
#include <deque>
#include <map>
#include <opencv2/core.hpp>
#include <utility>
#include <vector>

namespace facet::test {

struct ReferenceGrowth {
  cv::Mat labels;
  std::int32_t count = 0;
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> contacts;
};

inline ReferenceGrowth reference_grow(const cv::Mat& edge_mask, const cv::Mat& points,
                                      int connectivity, int min_size_px, int radius_px,
                                      double max_distance_m) {
  const int rows = edge_mask.rows;
  const int cols = edge_mask.cols;
  auto valid = [&](int y, int x) { return points.at<cv::Vec3f>(y, x)[2] > 0.F; };
  auto surface = [&](int y, int x) {
    return edge_mask.at<unsigned char>(y, x) == 0 && valid(y, x);
  };

  ReferenceGrowth out;
  out.labels = cv::Mat::zeros(rows, cols, CV_32SC1);
  cv::Mat visited = cv::Mat::zeros(rows, cols, CV_8UC1);
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      if (visited.at<unsigned char>(y, x) || !surface(y, x)) continue;
      std::vector<cv::Point> region;
      std::deque<cv::Point> queue{{x, y}};
      visited.at<unsigned char>(y, x) = 1;
      while (!queue.empty()) {
        const cv::Point p = queue.front();
        queue.pop_front();
        region.push_back(p);
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            if ((dx == 0 && dy == 0) || (connectivity == 4 && dx != 0 && dy != 0)) continue;
            const cv::Point q(p.x + dx, p.y + dy);
            if (q.x < 0 || q.y < 0 || q.x >= cols || q.y >= rows) continue;
            if (visited.at<unsigned char>(q) || !surface(q.y, q.x)) continue;
            visited.at<unsigned char>(q) = 1;
            queue.push_back(q);
          }
        }
      }
      if (static_cast<int>(region.size()) < min_size_px) continue;
      ++out.count;
      for (const cv::Point& p : region)
        out.labels.at<std::int32_t>(p) = out.count;
    }
  }

  // Assignment in synchronous rounds: each round reads the labels as they were before it.
  const float gate_sq = static_cast<float>(max_distance_m * max_distance_m);
  for (int round = 1; round <= radius_px; ++round) {
    const cv::Mat before = out.labels.clone();
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) {
        if (before.at<std::int32_t>(y, x) != 0 || !valid(y, x)) continue;
        const cv::Vec3f p = points.at<cv::Vec3f>(y, x);
        float best_sq = gate_sq;
        std::int32_t best_label = 0;
        for (int qy = y - 1; qy <= y + 1; ++qy) {
          for (int qx = x - 1; qx <= x + 1; ++qx) {
            if (qx < 0 || qy < 0 || qx >= cols || qy >= rows) continue;
            if (before.at<std::int32_t>(qy, qx) == 0) continue;
            const cv::Vec3f q = points.at<cv::Vec3f>(qy, qx);
            const float dx = q[0] - p[0];
            const float dy = q[1] - p[1];
            const float dz = q[2] - p[2];
            const float distance_sq = dx * dx + dy * dy + dz * dz;
            if (distance_sq < best_sq) {  // raster order: the first of equals wins
              best_sq = distance_sq;
              best_label = before.at<std::int32_t>(qy, qx);
            }
          }
        }
        if (best_label == 0) continue;
        out.labels.at<std::int32_t>(y, x) = best_label;
      }
    }
  }

  // Contacts: all 8 neighbours of every pixel; a < b counts each unordered pixel pair once.
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      const std::int32_t a = out.labels.at<std::int32_t>(y, x);
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int qx = x + dx;
          const int qy = y + dy;
          if ((dx == 0 && dy == 0) || qx < 0 || qy < 0 || qx >= cols || qy >= rows) continue;
          const std::int32_t b = out.labels.at<std::int32_t>(qy, qx);
          if (a != 0 && b != 0 && a < b) ++out.contacts[{a, b}];
        }
      }
    }
  }
  return out;
}

}  // namespace facet::test
