// The optimised stages against straightforward reference implementations (plain loops, double
// precision, written from the definitions) on a real frame.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <optional>

#include "normals/cross_stage.hpp"
#include "normals/pca_stage.hpp"
#include "normals_test_support.hpp"

namespace {

using facet::normals::CrossStage;
using facet::normals::PcaStage;
using namespace facet::test;

struct SpaceDef {
  std::string space;
  std::string image_depth;
  double depth_scale;
};

// The point of pixel (u, v) in the space, or nothing for invalid depth.
std::optional<Eigen::Vector3d> point(const facet::DepthImage& image, const SpaceDef& s, int u,
                                     int v) {
  const double mm = image.depth.at<std::uint16_t>(v, u);
  if (mm == 0) return std::nullopt;
  if (s.space == "metric") {
    const double z = mm / 1000.0;
    const auto& c = image.camera;
    return Eigen::Vector3d((u - c.cx) * z / c.fx, (v - c.cy) * z / c.fy, z);
  }
  const double scale =
      s.depth_scale * (s.image_depth == "disparity" ? image.depth.cols / 320.0 : 1.0);
  const double z = s.image_depth == "disparity" ? raw_disparity(mm) : mm;
  return Eigen::Vector3d(u, v, z * scale);
}

Eigen::Vector3d towards_camera(Eigen::Vector3d n, const Eigen::Vector3d& p, const SpaceDef& s) {
  const double facing = s.space == "metric" ? n.dot(p) : n.z();
  return facing > 0.0 ? -n : n;
}

cv::Mat reference_cross(const facet::DepthImage& image, const SpaceDef& s,
                        const std::string& triangle, int r) {
  cv::Mat out(image.depth.size(), CV_32FC3, cv::Scalar::all(std::nan("")));
  for (int v = r; v < out.rows - r; ++v) {
    for (int u = r; u < out.cols - r; ++u) {
      const auto p = point(image, s, u, v);
      Eigen::Vector3d n;
      if (triangle == "paper") {
        const auto a = point(image, s, u - r, v - r);
        const auto b = point(image, s, u + r, v - r);
        const auto c = point(image, s, u, v + r);
        if (!p || !a || !b || !c) continue;
        n = (*b - *a).cross(*c - *a);
      } else {
        const auto w = point(image, s, u - r, v);
        const auto e = point(image, s, u + r, v);
        const auto no = point(image, s, u, v - r);
        const auto so = point(image, s, u, v + r);
        if (!p || !w || !e || !no || !so) continue;
        n = (*e - *w).cross(*so - *no);
      }
      n = towards_camera(n.normalized(), *p, s);
      out.at<cv::Vec3f>(v, u) = cv::Vec3f(static_cast<float>(n.x()), static_cast<float>(n.y()),
                                          static_cast<float>(n.z()));
    }
  }
  return out;
}

// Box mean of the valid normals around each valid normal.
cv::Mat reference_smoothing(const cv::Mat& normals, int radius, bool renormalize) {
  cv::Mat out(normals.size(), CV_32FC3, cv::Scalar::all(std::nan("")));
  for (int v = 0; v < normals.rows; ++v) {
    for (int u = 0; u < normals.cols; ++u) {
      if (!has_normal(normals, v, u)) continue;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      int count = 0;
      for (int dv = -radius; dv <= radius; ++dv) {
        for (int du = -radius; du <= radius; ++du) {
          const int y = v + dv;
          const int x = u + du;
          if (x < 0 || y < 0 || x >= normals.cols || y >= normals.rows) continue;
          if (!has_normal(normals, y, x)) continue;
          sum += normal_at(normals, y, x);
          ++count;
        }
      }
      const Eigen::Vector3d n = renormalize ? sum.normalized() : Eigen::Vector3d(sum / count);
      out.at<cv::Vec3f>(v, u) = cv::Vec3f(static_cast<float>(n.x()), static_cast<float>(n.y()),
                                          static_cast<float>(n.z()));
    }
  }
  return out;
}

// Largest component difference where both have a normal; the NaN patterns must be equal.
double max_difference(const cv::Mat& a, const cv::Mat& b, int* mismatched_nan) {
  double worst = 0.0;
  *mismatched_nan = 0;
  for (int v = 0; v < a.rows; ++v) {
    for (int u = 0; u < a.cols; ++u) {
      if (has_normal(a, v, u) != has_normal(b, v, u)) {
        ++*mismatched_nan;
        continue;
      }
      if (!has_normal(a, v, u)) continue;
      worst = std::max(worst, (normal_at(a, v, u) - normal_at(b, v, u)).cwiseAbs().maxCoeff());
    }
  }
  return worst;
}

const SpaceDef kSpaces[] = {{"image", "disparity", 1.0},
                            {"image", "mm", 1.0},
                            {"image", "disparity", 3.0},
                            {"metric", "disparity", 1.0}};

TEST(ReferenceOnRealFrame, CrossMatchesTheDefinition) {
  const auto frame = real_frame();
  for (const auto& s : kSpaces) {
    for (const std::string triangle : {"paper", "centred"}) {
      for (const int r : {1, 2, 3}) {
        const cv::Mat expected = reference_cross(frame, s, triangle, r);
        const cv::Mat actual = run_normals<CrossStage>(frame, {{"space", s.space},
                                                               {"image_depth", s.image_depth},
                                                               {"depth_scale", s.depth_scale},
                                                               {"triangle", triangle},
                                                               {"radius", std::int64_t{r}}});
        int mismatched = 0;
        const double worst = max_difference(expected, actual, &mismatched);
        EXPECT_EQ(mismatched, 0) << s.space << "/" << s.image_depth << " " << triangle << " r" << r;
        EXPECT_LT(worst, 2e-4) << s.space << "/" << s.image_depth << " " << triangle << " r" << r;
      }
    }
  }
}

TEST(ReferenceOnRealFrame, SmoothedCrossMatchesTheDefinition) {
  const auto frame = real_frame();
  const SpaceDef s{"image", "disparity", 1.0};
  const cv::Mat raw = reference_cross(frame, s, "paper", 2);
  for (const int radius : {1, 2}) {
    for (const bool renormalize : {false, true}) {
      const cv::Mat expected = reference_smoothing(raw, radius, renormalize);
      const cv::Mat actual = run_normals<CrossStage>(
          frame, {{"smooth_radius", std::int64_t{radius}}, {"renormalize", renormalize}});
      int mismatched = 0;
      const double worst = max_difference(expected, actual, &mismatched);
      EXPECT_EQ(mismatched, 0) << "R" << radius << " renormalize " << renormalize;
      EXPECT_LT(worst, 2e-4) << "R" << radius << " renormalize " << renormalize;
    }
  }
}

// PCA by the book: collect the window's valid points, covariance around their mean, iterative
// eigen solver. Pixels where the two smallest eigenvalues are nearly equal have no well-defined
// normal and are skipped (counted).
TEST(ReferenceOnRealFrame, PcaMatchesTheDefinition) {
  const auto frame = real_frame();
  for (const auto& s : {kSpaces[0], kSpaces[3]}) {
    for (const int window : {3, 5}) {
      const double fraction = 0.5;
      const int needed = std::max(3, static_cast<int>(std::ceil(fraction * window * window)));
      const cv::Mat actual = run_normals<PcaStage>(frame, {{"space", s.space},
                                                           {"image_depth", s.image_depth},
                                                           {"window", std::int64_t{window}},
                                                           {"min_valid_fraction", fraction}});
      const int h = window / 2;
      int mismatched = 0;
      int compared = 0;
      int ill_conditioned = 0;
      int ambiguous_side = 0;
      double worst = 0.0;
      for (int v = 0; v < actual.rows; ++v) {
        for (int u = 0; u < actual.cols; ++u) {
          std::vector<Eigen::Vector3d> points;
          const auto centre = point(frame, s, u, v);
          const bool inside = u >= h && v >= h && u < actual.cols - h && v < actual.rows - h;
          if (centre && inside) {
            for (int dv = -h; dv <= h; ++dv) {
              for (int du = -h; du <= h; ++du) {
                if (const auto p = point(frame, s, u + du, v + dv)) points.push_back(*p);
              }
            }
          }
          const bool expected_normal =
              centre && inside && static_cast<int>(points.size()) >= needed;
          if (expected_normal != has_normal(actual, v, u)) {
            ++mismatched;
            continue;
          }
          if (!expected_normal) continue;
          Eigen::Vector3d mean = Eigen::Vector3d::Zero();
          for (const auto& p : points)
            mean += p;
          mean /= static_cast<double>(points.size());
          Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
          for (const auto& p : points)
            cov += (p - mean) * (p - mean).transpose();
          cov /= static_cast<double>(points.size());
          const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
          const auto& lambda = solver.eigenvalues();
          if (lambda(1) - lambda(0) < 1e-3 * lambda(2)) {
            ++ill_conditioned;
            continue;
          }
          const Eigen::Vector3d n = towards_camera(solver.eigenvectors().col(0), *centre, s);
          // A normal almost perpendicular to the line of sight has no reliable side.
          const double facing = s.space == "metric" ? n.dot(centre->normalized()) : n.z();
          if (std::abs(facing) < 1e-2) {
            ++ambiguous_side;
            continue;
          }
          worst = std::max(worst, (n - normal_at(actual, v, u)).cwiseAbs().maxCoeff());
          ++compared;
        }
      }
      EXPECT_EQ(mismatched, 0) << s.space << " window " << window;
      EXPECT_GT(compared, 100000) << s.space << " window " << window;
      // Degenerate windows (e.g. a few collinear points at a hole's rim) are rare.
      EXPECT_LT(ill_conditioned + ambiguous_side, compared / 20) << s.space << " window " << window;
      EXPECT_LT(worst, 1e-3) << s.space << " window " << window;
    }
  }
}

}  // namespace
