// edges.max and edges.avg: the score formula against a plain double-precision reference, borders,
// invalid pixels, and what real geometry (planes, creases, depth steps) produces.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <filesystem>
#include <opencv2/imgproc.hpp>

#include "edges/normal_edge_score.hpp"
#include "facet/testing/reverse_runner.hpp"
#include "facet/types/images.hpp"
#include "reference_edges.hpp"
#include "surface_pipeline.hpp"
#include "surface_test_geometry.hpp"
#include "synthetic_scene.hpp"

namespace facet::test {
namespace {

const std::filesystem::path kMosd = std::filesystem::path(FACET_TEST_DATA_DIR) / "mosd";

NormalImage constant_normals(int width, int height, cv::Vec3f normal) {
  NormalImage image;
  image.normals = cv::Mat(height, width, CV_32FC3, cv::Scalar(normal[0], normal[1], normal[2]));
  return image;
}

Eigen::Isometry3d box_pose_showing_three_faces() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  pose.linear() = (Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  return pose;
}

// Pixels whose 4-neighbour has another face id, both faces present: the creases and steps.
cv::Mat face_boundaries(const cv::Mat& face) {
  cv::Mat boundary = cv::Mat::zeros(face.size(), CV_8UC1);
  for (int y = 0; y + 1 < face.rows; ++y) {
    for (int x = 0; x + 1 < face.cols; ++x) {
      const int here = face.at<int>(y, x);
      const int right = face.at<int>(y, x + 1);
      const int below = face.at<int>(y + 1, x);
      if (here == 0) continue;
      if (right != 0 && right != here) boundary.at<unsigned char>(y, x) = 255;
      if (below != 0 && below != here) boundary.at<unsigned char>(y, x) = 255;
    }
  }
  return boundary;
}

// Edge pixels that are farther than `reach_px` (Chebyshev) from any invalid normal or border.
int interior_edges(const EdgeImage& edges, const cv::Mat& depth_valid, int reach_px) {
  cv::Mat invalid;
  cv::compare(depth_valid, 0, invalid, cv::CMP_EQ);
  cv::Mat padded;
  cv::copyMakeBorder(invalid, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(255));
  cv::Mat near;
  cv::dilate(padded, near, cv::Mat::ones(2 * reach_px + 1, 2 * reach_px + 1, CV_8UC1));
  near = near(cv::Rect(1, 1, invalid.cols, invalid.rows));
  cv::Mat interior;
  cv::bitwise_and(edges.mask, ~near, interior);
  return cv::countNonZero(interior);
}

TEST(NormalEdges, ConstantNormalsAreSurfaceExceptTheBorderWithinReach) {
  for (const int reach : {1, 3}) {
    const EdgeImage edges =
        run_edges(constant_normals(20, 16, {0.F, 0.F, -1.F}), {{"pixels", std::int64_t{reach}}});
    for (int y = 0; y < 16; ++y) {
      for (int x = 0; x < 20; ++x) {
        const bool border = x < reach || y < reach || x >= 20 - reach || y >= 16 - reach;
        EXPECT_EQ(edges.mask.at<unsigned char>(y, x), border ? 255 : 0)
            << "pixels=" << reach << " at " << x << "," << y;
        EXPECT_FLOAT_EQ(edges.score.at<float>(y, x), border ? 0.F : 1.F);
      }
    }
  }
}

TEST(NormalEdges, OneTiltedNeighbourGivesTheMeanOverThreePixels) {
  // A single normal at 60 degrees: its dot with the others is 0.5. With pixels = 3, a pixel two
  // steps east of it averages (1 + 1 + 0.5) / 3 along W for 'max' ...
  NormalImage image = constant_normals(21, 21, {0.F, 0.F, -1.F});
  image.normals.at<cv::Vec3f>(10, 10) =
      cv::Vec3f(0.F, std::sin(static_cast<float>(CV_PI / 3)), -0.5F);
  const EdgeImage max_edges = run_edges(image, {{"pixels", std::int64_t{3}}});
  EXPECT_NEAR(max_edges.score.at<float>(10, 12), 2.5F / 3.F, 1e-6);
  // ... and for 'avg' only one of the 8·3 products is 0.5.
  const EdgeImage avg_edges = run_edges<edges::AvgNormalEdges>(image);
  EXPECT_NEAR(avg_edges.score.at<float>(10, 12), (24.F - 0.5F) / 24.F, 1e-6);
  // Diagonals step in x and y at once: (13, 13) sees it along NW at k = 3, (13, 12) never.
  EXPECT_NEAR(max_edges.score.at<float>(13, 13), 2.5F / 3.F, 1e-6);
  EXPECT_FLOAT_EQ(max_edges.score.at<float>(13, 12), 1.F);
  // The tilted pixel itself sees 0.5 in every product.
  EXPECT_NEAR(max_edges.score.at<float>(10, 10), 0.5F, 1e-6);
  EXPECT_NEAR(avg_edges.score.at<float>(10, 10), 0.5F, 1e-6);
  // With pixels = 1 the neighbour's single product decides.
  const EdgeImage single = run_edges(image, {{"pixels", std::int64_t{1}}});
  EXPECT_NEAR(single.score.at<float>(10, 11), 0.5F, 1e-6);
  EXPECT_FLOAT_EQ(single.score.at<float>(10, 12), 1.F);
}

TEST(NormalEdges, ObtuseAnglesCountLikeTheirSupplement) {
  NormalImage image = constant_normals(9, 9, {0.F, 0.F, -1.F});
  image.normals.at<cv::Vec3f>(4, 5) = cv::Vec3f(0.F, 0.F, 1.F);  // flipped: |dot| = 1
  const EdgeImage edges = run_edges(image, {{"pixels", std::int64_t{1}}});
  EXPECT_FLOAT_EQ(edges.score.at<float>(4, 4), 1.F);
}

TEST(NormalEdges, InvalidNormalsAndTheirNeighboursAreEdgesWithFiniteScores) {
  NormalImage image = constant_normals(40, 30, {0.F, 0.F, -1.F});
  image.normals.at<cv::Vec3f>(15, 20) = cv::Vec3f(kNaN, kNaN, kNaN);
  image.normals.at<cv::Vec3f>(5, 30) = cv::Vec3f(0.F, kNaN, -1.F);  // one NaN component
  for (const bool avg : {false, true}) {
    const EdgeImage edges = avg ? run_edges<edges::AvgNormalEdges>(image) : run_edges(image);
    EXPECT_EQ(cv::checkRange(edges.score, true, nullptr, 0.0, 1.0 + 1e-6), true);
    for (const auto& [cy, cx] : {std::pair{15, 20}, std::pair{5, 30}}) {
      EXPECT_EQ(edges.mask.at<unsigned char>(cy, cx), 255);
      EXPECT_EQ(edges.score.at<float>(cy, cx), 0.F);
      // Every pixel that has it on one of its 8 rays within 3 pixels is an edge too.
      for (int k = 1; k <= 3; ++k) {
        EXPECT_EQ(edges.mask.at<unsigned char>(cy + k, cx - k), 255);
        EXPECT_EQ(edges.mask.at<unsigned char>(cy, cx + k), 255);
      }
    }
    // Off the rays, (2, 1) away from the hole, the pixel is surface.
    EXPECT_EQ(edges.mask.at<unsigned char>(17, 21), 0);
  }
}

// invalid_neighbours: skip leaves out the directions that meet a hole: the hole stays an edge,
// its surroundings keep the score of their valid directions, and a crease beside it still shows.
TEST(NormalEdges, SkippingInvalidNeighboursKeepsAHolesSurroundingsSurface) {
  NormalImage image = constant_normals(40, 30, {0.F, 0.F, -1.F});
  // A one-pixel dropout line, as a depth camera leaves along an object's outline.
  for (int y = 5; y < 25; ++y)
    image.normals.at<cv::Vec3f>(y, 20) = cv::Vec3f(kNaN, kNaN, kNaN);
  // A crease three pixels right of the line: the normals beyond it tilt by 60 degrees.
  for (int y = 0; y < 30; ++y) {
    for (int x = 24; x < 40; ++x)
      image.normals.at<cv::Vec3f>(y, x) =
          cv::Vec3f(std::sin(static_cast<float>(CV_PI / 3)), 0.F, -0.5F);
  }
  const Overrides skip{{"invalid_neighbours", std::string("skip")}};
  for (const bool avg : {false, true}) {
    const EdgeImage skipped =
        avg ? run_edges<edges::AvgNormalEdges>(image, skip) : run_edges(image, skip);
    const EdgeImage banded = avg ? run_edges<edges::AvgNormalEdges>(image) : run_edges(image);
    EXPECT_EQ(cv::checkRange(skipped.score, true, nullptr, 0.0, 1.0 + 1e-6), true);
    // The hole itself: no normal, score 0, an edge under either policy.
    EXPECT_EQ(skipped.score.at<float>(15, 20), 0.F);
    EXPECT_EQ(skipped.mask.at<unsigned char>(15, 20), 255);
    // Left of the line on the flat side: surface when skipped, an edge band when not.
    for (int x = 17; x <= 19; ++x) {
      EXPECT_FLOAT_EQ(skipped.score.at<float>(15, x), 1.F) << "x=" << x;
      EXPECT_EQ(skipped.mask.at<unsigned char>(15, x), 0) << "x=" << x;
      EXPECT_EQ(banded.mask.at<unsigned char>(15, x), 255) << "x=" << x;
    }
    // The crease beside the hole is still seen from its own side of it ('max': an edge).
    EXPECT_LT(skipped.score.at<float>(15, 23), 1.F);
    if (!avg) {
      EXPECT_EQ(skipped.mask.at<unsigned char>(15, 23), 255);
    }
  }
  // Skipping agrees with the plain reference, min and mean, here and on a real frame with holes.
  const RealFrame frame = load_mosd_frame(kMosd, "learn0");
  for (const NormalImage* normals : std::array<const NormalImage*, 2>{&image, &frame.normals}) {
    for (const bool take_min : {true, false}) {
      const EdgeImage edges =
          take_min ? run_edges(*normals, skip) : run_edges<edges::AvgNormalEdges>(*normals, skip);
      const cv::Mat reference = reference_edge_score(normals->normals, 3, take_min, true);
      cv::Mat score;
      edges.score.convertTo(score, CV_64F);
      EXPECT_LE(cv::norm(score, reference, cv::NORM_INF), 1e-6) << (take_min ? "max" : "avg");
    }
  }
  // And on the real frame, skipping marks fewer edges: the bands around its holes are gone.
  EXPECT_LT(cv::countNonZero(run_edges(frame.normals, skip).mask),
            cv::countNonZero(run_edges(frame.normals).mask));
}

TEST(NormalEdges, MaxScoreNeverExceedsAvgScoreOnARealFrame) {
  const RealFrame frame = load_mosd_frame(kMosd, "learn0");
  for (const int reach : {1, 3}) {
    const Overrides params{{"pixels", std::int64_t{reach}}};
    const EdgeImage max_edges = run_edges(frame.normals, params);
    const EdgeImage avg_edges = run_edges<edges::AvgNormalEdges>(frame.normals, params);
    cv::Mat excess = max_edges.score - avg_edges.score;
    double worst = 0.0;
    cv::minMaxLoc(excess, nullptr, &worst);
    EXPECT_LE(worst, 1e-6) << "pixels=" << reach;
    // And 'avg' really is different: it finds fewer edges.
    EXPECT_LT(cv::countNonZero(avg_edges.mask), cv::countNonZero(max_edges.mask));
  }
}

TEST(NormalEdges, OptimisedStagesAgreeWithThePlainReferenceOnRealFrames) {
  for (const char* stem : {"learn0", "learn18"}) {
    const RealFrame frame = load_mosd_frame(kMosd, stem);
    for (const int reach : {1, 3}) {
      for (const bool take_min : {true, false}) {
        const Overrides params{{"pixels", std::int64_t{reach}}, {"threshold", 0.85}};
        const EdgeImage edges = take_min ? run_edges(frame.normals, params)
                                         : run_edges<edges::AvgNormalEdges>(frame.normals, params);
        const cv::Mat reference = reference_edge_score(frame.normals.normals, reach, take_min);
        cv::Mat score;
        edges.score.convertTo(score, CV_64F);
        EXPECT_LE(cv::norm(score, reference, cv::NORM_INF), 1e-6)
            << stem << " pixels=" << reach << (take_min ? " max" : " avg");
        int mismatches = 0;
        for (int y = 0; y < score.rows; ++y) {
          for (int x = 0; x < score.cols; ++x) {
            const double ref = reference.at<double>(y, x);
            if (std::abs(ref - 0.85) < 1e-6) continue;  // too close to call in float
            if ((edges.mask.at<unsigned char>(y, x) == 255) != (ref <= 0.85)) ++mismatches;
          }
        }
        EXPECT_EQ(mismatches, 0);
        // The frame has both edges and surfaces, so the comparison is not vacuous.
        const int edge_px = cv::countNonZero(edges.mask);
        EXPECT_GT(edge_px, 1000);
        EXPECT_LT(edge_px, static_cast<int>(edges.mask.total()) - 1000);
      }
    }
  }
}

TEST(NormalEdges, BandsOfRowsScoredApartGiveTheSameImage) {
  const RealFrame frame = load_mosd_frame(kMosd, "learn0");
  for (const int reach : {1, 3}) {
    edges::NormalEdgeScorer scorer(reach, edges::DirectionCombine::min);
    const cv::Mat whole = scorer.score(frame.normals.normals);
    facet::testing::ReverseRunner runner(4);
    const cv::Mat banded = scorer.score(frame.normals.normals, &runner);
    EXPECT_EQ(runner.runs(), 1) << "the image was not split";
    EXPECT_EQ(cv::norm(whole, banded, cv::NORM_INF), 0.0) << "pixels=" << reach;
  }
}

class TiltedPlane : public ::testing::TestWithParam<double> {};

TEST_P(TiltedPlane, HasNoEdgesAwayFromTheBorderAndHoles) {
  const double tilt = GetParam() * CV_PI / 180.0;
  const std::array<Eigen::Vector3d, 2> axes = {Eigen::Vector3d::UnitX(), Eigen::Vector3d(1, 1, 0)};
  for (const Eigen::Vector3d& axis : axes) {
    const Eigen::Vector3d normal =
        Eigen::AngleAxisd(tilt, axis.normalized()) * Eigen::Vector3d(0, 0, -1);
    SceneBuilder builder;
    builder.plane({0, 0, 1.0}, normal);
    const SceneResult result = run_scene(builder);
    cv::Mat valid;
    cv::compare(result.scene.depth_m, 0.F, valid, cv::CMP_GT);
    cv::Mat in_range;
    cv::compare(result.scene.depth_m, 4.F, in_range, cv::CMP_LE);
    valid &= in_range;
    ASSERT_GT(cv::countNonZero(valid), 100000);
    // Normals reach r = 2 pixels, edges R = 3 more.
    EXPECT_EQ(interior_edges(result.edges, valid, 5), 0) << GetParam() << " deg";
    EXPECT_EQ(result.grown.patches.count, 1) << GetParam() << " deg";
  }
}

INSTANTIATE_TEST_SUITE_P(UpTo70Degrees, TiltedPlane, ::testing::Values(0.0, 30.0, 55.0, 70.0));

TEST(NormalEdges, BoxCreasesAreEdges) {
  SceneBuilder builder;
  builder.box(box_pose_showing_three_faces(), {0.1, 0.1, 0.1});
  const SceneResult result = run_scene(builder);
  const cv::Mat creases = face_boundaries(result.scene.face);
  ASSERT_GT(cv::countNonZero(creases), 200);
  cv::Mat missed;
  cv::bitwise_and(creases, ~result.edges.mask, missed);
  EXPECT_EQ(cv::countNonZero(missed), 0);
}

TEST(NormalEdges, ThreePixelsGiveBroaderCreaseEdgesThanOne) {
  SceneBuilder builder;
  builder.box(box_pose_showing_three_faces(), {0.1, 0.1, 0.1});
  const RenderedScene scene = builder.render();
  const NormalImage normals = cross_normals(points_from_depth(scene.depth_m, scene.camera));
  const EdgeImage one = run_edges(normals, {{"pixels", std::int64_t{1}}});
  const EdgeImage three = run_edges(normals, {{"pixels", std::int64_t{3}}});
  const cv::Mat creases = face_boundaries(scene.face);
  cv::Mat missed_by_one;
  cv::bitwise_and(creases, ~one.mask, missed_by_one);
  cv::Mat missed_by_three;
  cv::bitwise_and(creases, ~three.mask, missed_by_three);
  // With one pixel, the normals blended across a crease (the triangle spans it) change little
  // from pixel to pixel, so the crease line has gaps; averaging three pixels closes them. This
  // is the paper's reason for three pixels: region growing needs closed edges.
  EXPECT_GT(cv::countNonZero(missed_by_one), 0);
  EXPECT_LT(cv::countNonZero(missed_by_one), cv::countNonZero(creases) / 4);
  EXPECT_EQ(cv::countNonZero(missed_by_three), 0);
  // Each crease band grows by about 2 pixels on each side.
  EXPECT_GT(cv::countNonZero(three.mask), cv::countNonZero(one.mask) + 2000);
}

TEST(NormalEdges, DepthStepBetweenParallelSurfacesIsAnEdge) {
  // Box front face and wall behind are parallel: only the jump itself can make the edge.
  SceneBuilder builder;
  builder.plane({0, 0, 1.3}, {0, 0, -1});
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.05, 0.0, 1.1);
  builder.box(pose, {0.1, 0.08, 0.1});
  const SceneResult result = run_scene(builder);
  const cv::Mat silhouette = face_boundaries(result.scene.object);
  ASSERT_GT(cv::countNonZero(silhouette), 300);
  cv::Mat missed;
  cv::bitwise_and(silhouette, ~result.edges.mask, missed);
  EXPECT_EQ(cv::countNonZero(missed), 0);
}

TEST(NormalEdges, SpecDocumentsEveryPortAndParameter) {
  for (const StageSpec& spec : {edges::MaxNormalEdges::spec(), edges::AvgNormalEdges::spec()}) {
    EXPECT_EQ(spec.concurrency(), Concurrency::clonable);
    for (const auto& port : spec.inputs())
      EXPECT_FALSE(port.doc.empty()) << port.name;
    for (const auto& port : spec.outputs())
      EXPECT_FALSE(port.doc.empty()) << port.name;
    for (const auto& param : spec.params()) {
      EXPECT_FALSE(param.doc.empty()) << param.name;
      EXPECT_FALSE(param.options.origin.empty()) << param.name;
    }
    EXPECT_EQ(std::get<std::int64_t>(spec.find_param("pixels")->default_value), 3);
    EXPECT_EQ(std::get<double>(spec.find_param("threshold")->default_value), 0.85);
  }
}

}  // namespace
}  // namespace facet::test
