// grow.surfaces: flood fill, minimum size, the gated assignment pass and adjacency, on hand-made
// inputs, on exact synthetic geometry and against a plain reference on real frames.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <set>

#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "reference_growing.hpp"
#include "surface_pipeline.hpp"
#include "surface_test_geometry.hpp"
#include "synthetic_scene.hpp"

namespace facet::test {
namespace {

const std::filesystem::path kMosd = std::filesystem::path(FACET_TEST_DATA_DIR) / "mosd";

// The hand-made inputs are a few dozen pixels across; tests of the pixel counts themselves take
// them as given instead of scaled to a 640 x 480 image (facet/algo/pixel_scale.hpp).
constexpr std::pair<const char*, std::int64_t> kCountsAsGiven{"reference_area_px", 0};

// A fronto-parallel plane at depth_m (1 m unless given), 2 mm between pixels, every pixel
// surface.
struct FlatInput {
  EdgeImage edges;
  PointImage points;
};

FlatInput flat_input(int width, int height, float depth_m = 1.F) {
  FlatInput input;
  input.points.points = cv::Mat(height, width, CV_32FC3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      input.points.points.at<cv::Vec3f>(y, x) =
          cv::Vec3f(0.002F * static_cast<float>(x), 0.002F * static_cast<float>(y), depth_m);
    }
  }
  input.edges.mask = cv::Mat::zeros(height, width, CV_8UC1);
  input.edges.score = cv::Mat::ones(height, width, CV_32FC1);
  return input;
}

cv::Mat shifted(const cv::Mat& image, int dx, int dy, const cv::Scalar& fill) {
  cv::Mat out(image.size(), image.type(), fill);
  const cv::Rect source(std::max(0, -dx), std::max(0, -dy), image.cols - std::abs(dx),
                        image.rows - std::abs(dy));
  image(source).copyTo(out(source + cv::Point(dx, dy)));
  return out;
}

// The patch label most pixels of `region` carry (0 if none).
std::int32_t dominant_label(const cv::Mat& labels, const cv::Mat& region, double* share = nullptr) {
  std::map<std::int32_t, int> votes;
  int total = 0;
  for (int y = 0; y < labels.rows; ++y) {
    for (int x = 0; x < labels.cols; ++x) {
      if (region.at<unsigned char>(y, x) == 0) continue;
      ++total;
      const std::int32_t label = labels.at<std::int32_t>(y, x);
      if (label != 0) ++votes[label];
    }
  }
  std::int32_t best = 0;
  int best_votes = 0;
  for (const auto& [label, count] : votes) {
    if (count > best_votes) {
      best = label;
      best_votes = count;
    }
  }
  if (share != nullptr) *share = total > 0 ? static_cast<double>(best_votes) / total : 0.0;
  return best;
}

TEST(GrowSurfaces, AssignmentRespectsTheThreeDimensionalGate) {
  FlatInput input = flat_input(30, 30);
  input.edges.mask.colRange(14, 17).setTo(255);          // a 3-pixel edge band splits the plane
  input.points.points.at<cv::Vec3f>(10, 15)[2] = 1.05F;  // 5 cm behind its neighbours
  const Overrides params{{"min_size_px", std::int64_t{1}}};
  const GrowResult result = run_grow(input.edges, input.points, params);
  ASSERT_EQ(result.patches.count, 2);
  const cv::Mat& labels = result.patches.labels;
  EXPECT_EQ(labels.at<std::int32_t>(10, 15), 0) << "a far pixel must not be assigned";
  EXPECT_EQ(labels.at<std::int32_t>(10, 14), 1);
  EXPECT_EQ(labels.at<std::int32_t>(10, 16), 2);
  EXPECT_NE(labels.at<std::int32_t>(11, 15), 0);
  EXPECT_EQ(cv::countNonZero(labels == 0), 1);
  EXPECT_DOUBLE_EQ(result.unassigned_ratio, 1.0 / 900.0);
  ASSERT_EQ(result.adjacency.pairs.size(), 1U);
  EXPECT_EQ(result.adjacency.pairs[0], std::make_pair(1, 2));

  // A gate wider than the step lets it join.
  Overrides wide = params;
  wide["assign_max_distance_m"] = 0.06;
  EXPECT_NE(run_grow(input.edges, input.points, wide).patches.labels.at<std::int32_t>(10, 15), 0);
  // And a radius of 0 assigns nothing.
  Overrides none = params;
  none["assign_radius_px"] = std::int64_t{0};
  EXPECT_EQ(cv::countNonZero(run_grow(input.edges, input.points, none).patches.labels == 0), 90);
}

TEST(GrowSurfaces, AssignmentOnlyReachesRhoPixels) {
  FlatInput input = flat_input(40, 10);
  input.edges.mask.colRange(5, 40).setTo(255);
  const Overrides params{{"min_size_px", std::int64_t{1}}, {"assign_max_distance_m", 1.0}};
  const GrowResult result = run_grow(input.edges, input.points, params);
  const cv::Mat& labels = result.patches.labels;
  EXPECT_EQ(labels.at<std::int32_t>(5, 9), 1);   // 5 columns from the patch
  EXPECT_EQ(labels.at<std::int32_t>(5, 10), 0);  // 6 columns: out of reach
}

TEST(GrowSurfaces, ConnectivityDecidesWhetherADiagonalLineSeparates) {
  FlatInput input = flat_input(20, 20);
  for (int i = 0; i < 20; ++i)
    input.edges.mask.at<unsigned char>(i, i) = 255;
  const Overrides base{{"min_size_px", std::int64_t{1}}, {"assign_radius_px", std::int64_t{0}}};
  Overrides four = base;
  four["connectivity"] = std::int64_t{4};
  const GrowResult split = run_grow(input.edges, input.points, four);
  EXPECT_EQ(split.patches.count, 2);
  // Ids in raster order of the first pixel: the upper triangle starts at (row 0, col 1).
  EXPECT_EQ(split.patches.labels.at<std::int32_t>(0, 19), 1);
  EXPECT_EQ(split.patches.labels.at<std::int32_t>(19, 0), 2);
  Overrides eight = base;
  eight["connectivity"] = std::int64_t{8};
  EXPECT_EQ(run_grow(input.edges, input.points, eight).patches.count, 1);
}

TEST(GrowSurfaces, SmallRegionsReturnToThePoolAndJoinTheirNeighbour) {
  FlatInput input = flat_input(60, 60);
  cv::rectangle(input.edges.mask, cv::Rect(20, 20, 6, 6), cv::Scalar(255));  // 4x4 inside
  const GrowResult dropped = run_grow(input.edges, input.points, {kCountsAsGiven});
  EXPECT_EQ(dropped.patches.count, 1);
  EXPECT_EQ(cv::countNonZero(dropped.patches.labels != 1), 0);
  const GrowResult kept =
      run_grow(input.edges, input.points, {{"min_size_px", std::int64_t{16}}, kCountsAsGiven});
  EXPECT_EQ(kept.patches.count, 2);
  EXPECT_EQ(kept.patches.labels.at<std::int32_t>(22, 22), 2);
}

// An 8 x 8 region enclosed by edges: dropped at 1 and 1.2 m (needs 100 and 69 px), kept at 1.5
// and 3 m (needs 50: the floor) with the rule; dropped at every depth without it.
TEST(GrowSurfaces, FarRegionsAreKeptWithTheAreaNearOnesNeed) {
  const Overrides by_area{{"min_size_reference_depth_m", 1.0},
                          {"min_size_far_px", std::int64_t{50}},
                          {"assign_radius_px", std::int64_t{0}},
                          kCountsAsGiven};
  const Overrides fixed{{"assign_radius_px", std::int64_t{0}}, kCountsAsGiven};
  for (const float depth_m : {1.0F, 1.2F, 1.5F, 3.0F}) {
    FlatInput input = flat_input(60, 60, depth_m);
    cv::rectangle(input.edges.mask, cv::Rect(20, 20, 10, 10), cv::Scalar(255));  // 8x8 inside
    const GrowResult grown = run_grow(input.edges, input.points, by_area);
    const bool far = depth_m >= 1.5F;
    EXPECT_EQ(grown.patches.count, far ? 2 : 1) << depth_m;
    EXPECT_EQ(grown.patches.labels.at<std::int32_t>(25, 25), far ? 2 : 0) << depth_m;
    const GrowResult without = run_grow(input.edges, input.points, fixed);
    EXPECT_EQ(without.patches.count, 1) << depth_m;
    EXPECT_EQ(without.patches.labels.at<std::int32_t>(25, 25), 0) << depth_m;
  }
}

// The depth is each region's own mean: a small region at 1 m is dropped and one at 2 m kept in
// the same frame, and the ids stay consecutive in raster order (the kept one is 2, not 3).
TEST(GrowSurfaces, EachRegionIsJudgedAtItsOwnDepthAndIdsStayConsecutive) {
  FlatInput input = flat_input(60, 60, 1.F);
  cv::rectangle(input.edges.mask, cv::Rect(10, 5, 10, 10), cv::Scalar(255));   // near, 8x8
  cv::rectangle(input.edges.mask, cv::Rect(30, 30, 10, 10), cv::Scalar(255));  // far, 8x8
  for (int y = 31; y < 39; ++y) {
    for (int x = 31; x < 39; ++x)
      input.points.points.at<cv::Vec3f>(y, x)[2] = 2.F;
  }
  const GrowResult grown = run_grow(
      input.edges, input.points,
      {{"min_size_reference_depth_m", 1.0}, {"assign_radius_px", std::int64_t{0}}, kCountsAsGiven});
  EXPECT_EQ(grown.patches.count, 2);
  EXPECT_EQ(grown.patches.labels.at<std::int32_t>(0, 0), 1);
  EXPECT_EQ(grown.patches.labels.at<std::int32_t>(8, 12), 0);
  EXPECT_EQ(grown.patches.labels.at<std::int32_t>(34, 34), 2);
  EXPECT_EQ(cv::countNonZero(grown.patches.labels == 2), 64);
}

// A rendered box 7 cm wide, 2 m away in front of a wall: its front face, narrowed by its edge
// band, keeps a region of 50-99 px, a patch with the far rule and none without. The same box at
// half the size and half the distance covers the same pixels, and its region stays dropped.
TEST(GrowSurfaces, AFarBoxFaceBecomesAPatchWhereTheSameFootprintNearDoesNot) {
  struct Case {
    double depth_m;
    double half_m;
    bool patch_with_rule;
  };
  for (const Case& c : {Case{2.0, 0.035, true}, Case{1.0, 0.0175, false}}) {
    SceneBuilder builder;
    builder.plane({0.0, 0.0, c.depth_m + 0.3}, {0.0, 0.0, -1.0});
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.0, 0.0, c.depth_m);
    builder.box(pose, {c.half_m, c.half_m, c.half_m});
    const RenderedScene scene = builder.render();
    const PointImage points = points_from_depth(scene.depth_m, scene.camera, 4.0);
    const EdgeImage edges = run_edges(cross_normals(points));
    const Overrides no_assignment{{"assign_radius_px", std::int64_t{0}}};
    Overrides by_area = no_assignment;
    by_area["min_size_reference_depth_m"] = 1.0;
    const GrowResult fixed = run_grow(edges, points, no_assignment);
    const GrowResult grown = run_grow(edges, points, by_area);
    EXPECT_EQ(fixed.patches.count, 1) << c.depth_m;  // the wall
    ASSERT_EQ(grown.patches.count, c.patch_with_rule ? 2 : 1) << c.depth_m;
    if (!c.patch_with_rule) continue;
    const cv::Mat wall = scene.face == 1;
    const std::int32_t box_patch = dominant_label(grown.patches.labels, wall) == 1 ? 2 : 1;
    const cv::Mat box_pixels = grown.patches.labels == box_patch;
    const int box_px = cv::countNonZero(box_pixels);
    EXPECT_GE(box_px, 50);
    EXPECT_LT(box_px, 100);
    EXPECT_EQ(cv::countNonZero(box_pixels & wall), 0);
  }
}

// A frame whose surfaces are mostly too small to keep (a fine grid of edges, as noise or a
// grid of tiny objects gives) warns; a clean frame does not.
TEST(GrowSurfaces, WarnsWhenMostPixelsAreInNoPatch) {
  FlatInput input = flat_input(120, 120);
  EXPECT_TRUE(run_grow(input.edges, input.points, {kCountsAsGiven}).warnings.empty());
  for (int i = 0; i < 120; i += 8) {
    cv::line(input.edges.mask, {i, 0}, {i, 119}, cv::Scalar(255));
    cv::line(input.edges.mask, {0, i}, {119, i}, cv::Scalar(255));
  }
  const GrowResult noisy = run_grow(input.edges, input.points, {kCountsAsGiven});
  EXPECT_GT(noisy.unassigned_ratio, 0.25);
  ASSERT_EQ(noisy.warnings.size(), 1u);
  EXPECT_NE(noisy.warnings[0].find("no patch"), std::string::npos) << noisy.warnings[0];
  EXPECT_TRUE(run_grow(input.edges, input.points, {{"max_unassigned_ratio", 1.0}, kCountsAsGiven})
                  .warnings.empty());
}

// min_size_px is given for 640 x 480: a region of 18 x 18 = 324 px (enclosed by a 1-px edge
// line) is kept at 640 x 480 and in a 320 x 240 image (the count there is 25), and dropped in a
// 1280 x 960 one (400), where the same surface would cover four times the pixels.
TEST(GrowSurfaces, RegionSizesScaleWithTheImageArea) {
  const Overrides params{{"min_size_px", std::int64_t{100}}, {"assign_radius_px", std::int64_t{0}}};
  struct Case {
    int width;
    int height;
    bool kept;
  };
  for (const Case& c : {Case{640, 480, true}, Case{320, 240, true}, Case{1280, 960, false}}) {
    FlatInput input = flat_input(c.width, c.height);
    cv::rectangle(input.edges.mask, cv::Rect(40, 40, 20, 20), cv::Scalar(255));  // 18x18 inside
    const GrowResult grown = run_grow(input.edges, input.points, params);
    EXPECT_EQ(grown.patches.count, c.kept ? 2 : 1) << c.width;
    EXPECT_EQ(grown.patches.labels.at<std::int32_t>(50, 50), c.kept ? 2 : 0) << c.width;
  }
  // A 4 x 4 region (16 px) at 320 x 240 with min_size_px 20: dropped when the count is taken as
  // given, kept when it is scaled (to 5).
  FlatInput small = flat_input(320, 240);
  cv::rectangle(small.edges.mask, cv::Rect(40, 40, 6, 6), cv::Scalar(255));  // 4x4 inside
  Overrides as_given = params;
  as_given["min_size_px"] = std::int64_t{20};
  as_given.insert(kCountsAsGiven);
  EXPECT_EQ(run_grow(small.edges, small.points, as_given).patches.count, 1);
  Overrides scaled = as_given;
  scaled["reference_area_px"] = std::int64_t{640 * 480};
  EXPECT_EQ(run_grow(small.edges, small.points, scaled).patches.count, 2);
}

TEST(GrowSurfaces, BoxFacesBecomeSeparateTouchingPatches) {
  SceneBuilder builder;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  pose.linear() = (Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  builder.box(pose, {0.1, 0.1, 0.1});
  const SceneResult result = run_scene(builder);
  const cv::Mat& labels = result.grown.patches.labels;

  std::set<std::int32_t> face_patches;
  int visible_faces = 0;
  for (int face = 1; face <= 6; ++face) {
    const cv::Mat pixels = result.scene.face == face;
    if (cv::countNonZero(pixels) < 2000) continue;
    ++visible_faces;
    double share = 0.0;
    const std::int32_t label = dominant_label(labels, pixels, &share);
    ASSERT_NE(label, 0) << "face " << face;
    // The rest: steep-face pixels whose neighbours are farther apart than the 3D gate.
    EXPECT_GT(share, 0.75) << "face " << face;
    // The patch holds little of other faces: only crease pixels assigned across the crease.
    double purity = 0.0;
    EXPECT_EQ(dominant_label(result.scene.face, labels == label, &purity), face);
    EXPECT_GT(purity, 0.97);
    face_patches.insert(label);
  }
  ASSERT_EQ(visible_faces, 3);
  EXPECT_EQ(face_patches.size(), 3U);
  EXPECT_EQ(result.grown.patches.count, 3);
  for (const std::int32_t a : face_patches) {
    for (const std::int32_t b : face_patches) {
      if (a < b) {
        EXPECT_TRUE(adjacent(result.grown.adjacency, a, b)) << a << "-" << b;
      }
    }
  }
}

TEST(GrowSurfaces, CylinderSideStaysOneSmoothPatch) {
  SceneBuilder builder;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  pose.linear() = Eigen::AngleAxisd(CV_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  builder.cylinder(pose, 0.08, 0.15);
  const SceneResult result = run_scene(builder);
  const cv::Mat side = result.scene.face == 1;
  ASSERT_GT(cv::countNonZero(side), 10000);
  double share = 0.0;
  const std::int32_t label = dominant_label(result.grown.patches.labels, side, &share);
  ASSERT_NE(label, 0);
  EXPECT_GT(share, 0.85);  // the rest: grazing-angle rims near the silhouette
  EXPECT_EQ(result.grown.patches.count, 1);
}

TEST(GrowSurfaces, DepthStepSeparatesPatchesAndTheGateKeepsSides) {
  SceneBuilder builder;
  builder.plane({0, 0, 1.3}, {0, 0, -1});
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.05, 0.0, 1.1);
  builder.box(pose, {0.1, 0.08, 0.1});
  const SceneResult result = run_scene(builder);
  const cv::Mat& labels = result.grown.patches.labels;
  const std::int32_t wall = dominant_label(labels, result.scene.object == 1);
  const std::int32_t box = dominant_label(labels, result.scene.object == 2);
  ASSERT_NE(wall, 0);
  ASSERT_NE(box, 0);
  EXPECT_NE(wall, box);
  // 20 cm apart in depth: the assignment never crosses the step.
  EXPECT_EQ(cv::countNonZero((labels == box) & (result.scene.object == 1)), 0);
  EXPECT_EQ(cv::countNonZero((labels == wall) & (result.scene.object == 2)), 0);
  EXPECT_TRUE(adjacent(result.grown.adjacency, wall, box));
}

TEST(GrowSurfaces, InvalidPixelsStayUnassignedAndNothingBecomesNaN) {
  SceneBuilder builder;
  builder.plane({0, 0, 1.0}, Eigen::Vector3d(0.2, -0.3, -1.0));
  RenderedScene scene = builder.render();
  scene.depth_m(cv::Rect(200, 150, 80, 60)).setTo(0.F);  // a hole
  for (int i = 0; i < 50; ++i)
    scene.depth_m.at<float>(50 + 7 * i % 380, 30 + 11 * i) = 0.F;
  const PointImage points = points_from_depth(scene.depth_m, scene.camera);
  const NormalImage normals = cross_normals(points);
  for (const bool avg : {false, true}) {
    const EdgeImage edges = avg ? run_edges<edges::AvgNormalEdges>(normals) : run_edges(normals);
    EXPECT_TRUE(cv::checkRange(edges.score, true, nullptr, 0.0, 1.0 + 1e-6));
    EXPECT_EQ(cv::countNonZero(edges.mask(cv::Rect(200, 150, 80, 60)) == 0), 0);
    const GrowResult grown = run_grow(edges, points);
    EXPECT_EQ(grown.patches.count, 1);
    EXPECT_EQ(cv::countNonZero((grown.patches.labels != 0) & (scene.depth_m == 0.F)), 0);
    EXPECT_GE(grown.unassigned_ratio, 0.0);
    EXPECT_LT(grown.unassigned_ratio, 0.05);
  }
}

TEST(GrowSurfaces, ShiftingTheSceneShiftsTheResultAndNothingElse) {
  SceneBuilder builder;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.2);
  pose.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 1, 0.3).normalized()).toRotationMatrix();
  builder.box(pose, {0.12, 0.08, 0.1});
  const SceneResult original = run_scene(builder);
  const int dx = 9;
  const int dy = -6;
  const cv::Scalar nan_fill = cv::Scalar::all(kNaN);
  NormalImage normals;
  normals.normals = shifted(original.normals.normals, dx, dy, nan_fill);
  PointImage points;
  points.points = shifted(original.points.points, dx, dy, nan_fill);
  const EdgeImage edges = run_edges(normals);
  const GrowResult grown = run_grow(edges, points);

  EXPECT_EQ(cv::norm(edges.score, shifted(original.edges.score, dx, dy, 0), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::countNonZero(edges.mask != shifted(original.edges.mask, dx, dy, 255)), 0);
  EXPECT_EQ(grown.patches.count, original.grown.patches.count);
  EXPECT_EQ(
      cv::countNonZero(grown.patches.labels != shifted(original.grown.patches.labels, dx, dy, 0)),
      0);
  EXPECT_EQ(grown.adjacency.pairs, original.grown.adjacency.pairs);
  EXPECT_EQ(grown.adjacency.contact_px, original.grown.adjacency.contact_px);
  EXPECT_GE(original.grown.patches.count, 2);
}

TEST(GrowSurfaces, AgreesWithThePlainReferenceOnRealFrames) {
  struct Case {
    const char* stem;
    int connectivity;
    int radius_px;
    double gate_m;
  };
  for (const Case& c :
       {Case{"learn0", 4, 5, 0.01}, Case{"learn18", 8, 5, 0.015}, Case{"learn20", 4, 3, 0.01}}) {
    const RealFrame frame = load_mosd_frame(kMosd, c.stem);
    const EdgeImage edges = run_edges(frame.normals, {{"threshold", 0.89}});
    const GrowResult grown = run_grow(edges, frame.points,
                                      {{"connectivity", std::int64_t{c.connectivity}},
                                       {"assign_radius_px", std::int64_t{c.radius_px}},
                                       {"assign_max_distance_m", c.gate_m}});
    const ReferenceGrowth reference =
        reference_grow(edges.mask, frame.points.points, c.connectivity, 100, c.radius_px, c.gate_m);
    ASSERT_EQ(grown.patches.count, reference.count) << c.stem;
    EXPECT_GT(grown.patches.count, 5) << c.stem;
    EXPECT_EQ(cv::countNonZero(grown.patches.labels != reference.labels), 0) << c.stem;
    ASSERT_EQ(grown.adjacency.pairs.size(), reference.contacts.size()) << c.stem;
    std::size_t i = 0;
    for (const auto& [pair, contacts] : reference.contacts) {
      EXPECT_EQ(grown.adjacency.pairs[i], pair);
      EXPECT_EQ(grown.adjacency.contact_px[i], contacts);
      ++i;
    }
    EXPECT_EQ(grown.adjacency.count, grown.patches.count);
  }
}

// The stage keeps its working buffers from frame to frame: a second frame of another size
// must come out exactly as from a fresh instance.
TEST(GrowSurfaces, ReusedInstanceMatchesAFreshOneAcrossFrameSizes) {
  FlatInput first = flat_input(30, 30);
  first.edges.mask.colRange(14, 17).setTo(255);
  FlatInput second = flat_input(37, 13);
  second.edges.mask.rowRange(4, 7).setTo(255);
  second.points.points.at<cv::Vec3f>(5, 20)[2] = 1.05F;
  const Overrides params{{"min_size_px", std::int64_t{1}}};
  testing::StageRunner<grow::GrowSurfaces> runner(params);
  for (const FlatInput* input : {&first, &second, &first}) {
    runner.set_input("edges", Packet::make(input->edges));
    runner.set_input("points", Packet::make(input->points));
    runner.run();
    const GrowResult fresh = run_grow(input->edges, input->points, params);
    const auto& labels = runner.output<LabelImage>("patches").labels;
    ASSERT_EQ(labels.size(), fresh.patches.labels.size());
    EXPECT_EQ(cv::countNonZero(labels != fresh.patches.labels), 0);
    EXPECT_EQ(runner.output<PatchAdjacency>("adjacency").pairs, fresh.adjacency.pairs);
  }
}

TEST(GrowSurfaces, SpecDocumentsEveryPortAndParameter) {
  const StageSpec spec = grow::GrowSurfaces::spec();
  for (const auto& port : spec.inputs())
    EXPECT_FALSE(port.doc.empty()) << port.name;
  for (const auto& port : spec.outputs())
    EXPECT_FALSE(port.doc.empty()) << port.name;
  for (const auto& param : spec.params()) {
    EXPECT_FALSE(param.doc.empty()) << param.name;
    EXPECT_FALSE(param.options.origin.empty()) << param.name;
  }
}

}  // namespace
}  // namespace facet::test
