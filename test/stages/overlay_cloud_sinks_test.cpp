// io.overlay: the picture of a segmented frame, and the palette it takes its colours from.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>
#include <tuple>
#include <type_traits>

#include "facet/framework/executor.hpp"
#include "facet/framework/registry.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "io/label_palette.hpp"
#include "io/overlay_sink.hpp"
#include "stage_test_support.hpp"

namespace {

using facet::DepthImage;
using facet::EdgeImage;
using facet::LabelImage;
using facet::Packet;
using facet::PointImage;
using facet::io::label_colour;
using facet::io::Rgb;
using facet::test::expect_stage_error;
using facet::test::TempDir;
using facet::test::write_text;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

template <class Image>
Image with_frame(Image image, const std::string& stem) {
  image.frame.stem = stem;
  return image;
}

cv::Vec3b bgr(const Rgb& c) {
  return {c.b, c.g, c.r};
}

bool is_grey(const cv::Vec3b& p) {
  return p[0] == p[1] && p[1] == p[2];
}

// The overlay's blend of grey `g` with a segment colour at the default alpha 0.5.
cv::Vec3b blend_half(std::uint8_t g, const Rgb& c) {
  const auto mix = [&](std::uint8_t channel) {
    return static_cast<std::uint8_t>((g * 128 + channel * 128) >> 8);
  };
  return {mix(c.b), mix(c.g), mix(c.r)};
}

cv::Mat read_colour(const std::filesystem::path& file) {
  return cv::imread(file.string(), cv::IMREAD_UNCHANGED);
}

// ---------------------------------------------------------------------------------------------
// The palette

TEST(LabelPalette, ColoursArePinned) {
  // Changing the palette changes every overlay and cloud written so far: do it deliberately,
  // and update docs/data-formats.md, which lists these colours.
  EXPECT_EQ(label_colour(1), (Rgb{67, 106, 200}));
  EXPECT_EQ(label_colour(2), (Rgb{96, 150, 18}));
  EXPECT_EQ(label_colour(3), (Rgb{255, 85, 234}));
  EXPECT_EQ(label_colour(4), (Rgb{24, 200, 171}));
  EXPECT_EQ(label_colour(12), (Rgb{30, 255, 143}));
}

TEST(LabelPalette, StableSaturatedAndDistinct) {
  std::set<std::tuple<int, int, int>> seen;
  for (std::uint32_t id = 1; id <= 1000; ++id) {
    const Rgb c = label_colour(id);
    EXPECT_EQ(c, label_colour(id)) << id;
    const int hi = std::max({c.r, c.g, c.b});
    const int lo = std::min({c.r, c.g, c.b});
    EXPECT_GE(hi - lo, 100) << "id " << id << " is too close to grey";
    seen.insert({c.r, c.g, c.b});
  }
  EXPECT_GT(seen.size(), 950U);
  // The first ids, those a frame of a few objects uses, are clearly apart from one another.
  for (std::uint32_t a = 1; a <= 12; ++a) {
    for (std::uint32_t b = a + 1; b <= 12; ++b) {
      const Rgb ca = label_colour(a);
      const Rgb cb = label_colour(b);
      const int distance = std::abs(ca.r - cb.r) + std::abs(ca.g - cb.g) + std::abs(ca.b - cb.b);
      EXPECT_GT(distance, 60) << a << " vs " << b;
    }
  }
}

TEST(LabelPalette, ParsesHexColours) {
  EXPECT_EQ(facet::io::parse_hex_colour("#ff00Aa"), (Rgb{255, 0, 170}));
  EXPECT_EQ(facet::io::parse_hex_colour("102030"), (Rgb{16, 32, 48}));
  EXPECT_FALSE(facet::io::parse_hex_colour("#ff00a"));
  EXPECT_FALSE(facet::io::parse_hex_colour("red"));
  EXPECT_FALSE(facet::io::parse_hex_colour("#gg0000"));
}

// ---------------------------------------------------------------------------------------------
// io.overlay

// A 12x8 scene: depth 1.0 m on the left half, 2.0 m on the right, one invalid pixel; segment 3 a
// 4x4 square on the left, segment 7 a 4x4 square on the right.
struct OverlayScene {
  DepthImage depth;
  LabelImage labels;
};

OverlayScene overlay_scene(const std::string& stem) {
  OverlayScene scene;
  scene.depth.frame.stem = stem;
  scene.depth.depth = cv::Mat(8, 12, CV_16UC1, cv::Scalar(1000));
  scene.depth.depth(cv::Rect(6, 0, 6, 8)).setTo(2000);
  scene.depth.depth.at<std::uint16_t>(0, 0) = 0;
  scene.labels.frame.stem = stem;
  scene.labels.labels = cv::Mat(8, 12, CV_32SC1, cv::Scalar(0));
  scene.labels.labels(cv::Rect(1, 2, 4, 4)).setTo(3);
  scene.labels.labels(cv::Rect(7, 2, 4, 4)).setTo(7);
  scene.labels.count = 7;
  return scene;
}

using OverlayRunner = facet::testing::StageRunner<facet::io::OverlaySink>;

cv::Mat run_overlay(OverlayRunner& sink, const OverlayScene& scene, const TempDir& dir,
                    const std::string& subdir = "overlay") {
  sink.set_input("depth", Packet::make(scene.depth));
  sink.set_input("labels", Packet::make(scene.labels));
  sink.run();
  return read_colour(dir / subdir / (scene.depth.frame.stem + ".png"));
}

TEST(OverlaySink, WritesBgrOfTheFrameSizeWithSegmentColoursOverGrey) {
  TempDir dir;
  OverlayRunner sink({{"dir", (dir / "overlay").string()}});
  const OverlayScene scene = overlay_scene("learn0");
  const cv::Mat out = run_overlay(sink, scene, dir);
  ASSERT_EQ(out.type(), CV_8UC3);
  ASSERT_EQ(out.cols, 12);
  ASSERT_EQ(out.rows, 8);

  // Two valid depths only: the auto range is [1 m, 2 m], so near is white and far is grey 48.
  EXPECT_EQ(out.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0)) << "invalid depth is black";
  EXPECT_EQ(out.at<cv::Vec3b>(7, 1), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(out.at<cv::Vec3b>(7, 10), cv::Vec3b(48, 48, 48));
  for (int y = 0; y < out.rows; ++y) {
    for (int x = 0; x < out.cols; ++x) {
      if (scene.labels.labels.at<std::int32_t>(y, x) == 0) {
        EXPECT_TRUE(is_grey(out.at<cv::Vec3b>(y, x))) << "label 0 at " << x << "," << y;
      }
    }
  }
  // Inside the squares: the segment's palette colour blended half over the grey.
  EXPECT_EQ(out.at<cv::Vec3b>(3, 2), blend_half(255, label_colour(3)));
  EXPECT_EQ(out.at<cv::Vec3b>(4, 3), blend_half(255, label_colour(3)));
  EXPECT_EQ(out.at<cv::Vec3b>(3, 8), blend_half(48, label_colour(7)));
  EXPECT_FALSE(is_grey(out.at<cv::Vec3b>(3, 2)));
  // Their borders: black by default.
  EXPECT_EQ(out.at<cv::Vec3b>(2, 1), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(out.at<cv::Vec3b>(5, 4), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(out.at<cv::Vec3b>(3, 10), cv::Vec3b(0, 0, 0));
}

TEST(OverlaySink, ASegmentKeepsItsColourFromFrameToFrame) {
  TempDir dir;
  OverlayRunner sink({{"dir", (dir / "overlay").string()},
                      {"alpha", 1.0},
                      {"draw_borders", false},
                      {"far_m", 3.0}});
  OverlayScene first = overlay_scene("a");
  OverlayScene second = overlay_scene("b");
  // In the second frame segment 3 moved to the right half and segment 7 is gone.
  second.labels.labels.setTo(0);
  second.labels.labels(cv::Rect(8, 1, 3, 3)).setTo(3);
  const cv::Mat out_a = run_overlay(sink, first, dir);
  const cv::Mat out_b = run_overlay(sink, second, dir);
  EXPECT_EQ(out_a.at<cv::Vec3b>(3, 2), bgr(label_colour(3)));
  EXPECT_EQ(out_b.at<cv::Vec3b>(2, 9), bgr(label_colour(3)));
  EXPECT_NE(label_colour(3), label_colour(7));
}

TEST(OverlaySink, FixedRangeAndMetreDepth) {
  TempDir dir;
  OverlayRunner sink({{"dir", dir.path().string()}, {"near_m", 0.5}, {"far_m", 2.5}});
  OverlayScene scene = overlay_scene("m");
  cv::Mat metres;
  scene.depth.depth.convertTo(metres, CV_32F, 0.001);
  metres.at<float>(0, 1) = kNaN;
  scene.depth.depth = metres;
  sink.set_input("depth", Packet::make(scene.depth));
  sink.set_input("labels", Packet::make(scene.labels));
  sink.run();
  const cv::Mat out = read_colour(dir / "m.png");
  // 1 m is a quarter of the way from 0.5 to 2.5 m: 48 + 0.75 * 207 = 203.25.
  EXPECT_EQ(out.at<cv::Vec3b>(7, 1), cv::Vec3b(203, 203, 203));
  EXPECT_EQ(out.at<cv::Vec3b>(7, 10), cv::Vec3b(100, 100, 100));  // 48 + 0.25 * 207
  EXPECT_EQ(out.at<cv::Vec3b>(0, 1), cv::Vec3b(0, 0, 0)) << "NaN is black";
}

TEST(OverlaySink, AutoRangeIgnoresAFewOutliers) {
  // 200 pixels from 1.0 to 1.199 m and one at 30 m: the stray pixel must not compress the grey
  // of the scene into a few levels.
  cv::Mat depth(10, 20, CV_16UC1);
  for (int i = 0; i < 200; ++i)
    depth.at<std::uint16_t>(i / 20, i % 20) = static_cast<std::uint16_t>(1000 + i);
  depth.at<std::uint16_t>(9, 19) = 30000;
  const auto range = facet::io::auto_grey_range(depth);
  EXPECT_NEAR(range.near_m, 1.001, 1e-9);
  EXPECT_NEAR(range.far_m, 1.198, 1e-9);
  EXPECT_EQ(facet::io::auto_grey_range(cv::Mat(3, 3, CV_16UC1, cv::Scalar(0))).far_m, 0.0);
}

TEST(OverlaySink, DrawsTheEdgeMaskWhenConnectedAndAsked) {
  TempDir dir;
  const OverlayScene scene = overlay_scene("e");
  EdgeImage edges;
  edges.mask = cv::Mat(8, 12, CV_8UC1, cv::Scalar(0));
  edges.mask.at<std::uint8_t>(7, 5) = 255;
  edges.mask.at<std::uint8_t>(3, 2) = 255;  // inside segment 3
  edges.mask.at<std::uint8_t>(0, 0) = 255;  // no depth: stays black
  {
    OverlayRunner sink({{"dir", (dir / "on").string()}, {"edge_colour", std::string("#00ff80")}});
    sink.set_input("edges", Packet::make(edges));
    const cv::Mat out = run_overlay(sink, scene, dir, "on");
    EXPECT_EQ(out.at<cv::Vec3b>(7, 5), cv::Vec3b(128, 255, 0));
    EXPECT_EQ(out.at<cv::Vec3b>(3, 2), cv::Vec3b(128, 255, 0));
    EXPECT_EQ(out.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
  }
  {
    OverlayRunner sink({{"dir", (dir / "off").string()}, {"draw_edges", false}});
    sink.set_input("edges", Packet::make(edges));
    const cv::Mat out = run_overlay(sink, scene, dir, "off");
    EXPECT_TRUE(is_grey(out.at<cv::Vec3b>(7, 5)));
  }
}

TEST(OverlaySink, EmptyLabelPacketWritesNothing) {
  TempDir dir;
  OverlayRunner sink({{"dir", dir.path().string()}});
  sink.set_input("depth", Packet::make(overlay_scene("x").depth));
  sink.set_input("labels", Packet{});
  sink.run();
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(OverlaySink, BadInputsAndParamsAreClearErrors) {
  TempDir dir;
  OverlayRunner sink({{"dir", dir.path().string()}});
  OverlayScene scene = overlay_scene("bad");
  scene.labels.labels = cv::Mat(4, 4, CV_32SC1, cv::Scalar(1));
  sink.set_input("depth", Packet::make(scene.depth));
  sink.set_input("labels", Packet::make(scene.labels));
  expect_stage_error([&] { sink.run(); }, {"'depth'", "'labels'", "differ in size"});

  expect_stage_error(
      [&] {
        OverlayRunner bad({{"dir", dir.path().string()}, {"edge_colour", std::string("red")}});
      },
      {"edge_colour", "red", "#rrggbb"});
  expect_stage_error(
      [&] {
        OverlayRunner bad({{"dir", dir.path().string()}, {"near_m", 2.0}, {"far_m", 1.0}});
      },
      {"far_m", "near_m"});
}

TEST(OverlayAndCloudSinks, AFileThatCannotBeWrittenIsAnErrorNamingIt) {
  TempDir dir;
  std::filesystem::create_directories(dir / "x.png");  // a folder where the file should go
  OverlayRunner overlay({{"dir", dir.path().string()}});
  const OverlayScene scene = overlay_scene("x");
  overlay.set_input("depth", Packet::make(scene.depth));
  overlay.set_input("labels", Packet::make(scene.labels));
  expect_stage_error([&] { overlay.run(); }, {"cannot write", (dir / "x.png").string()});
}

// ---------------------------------------------------------------------------------------------
// An output folder that cannot be made stops a run with an error naming the node and the folder.

template <class Sink>
std::string open_error_of_a_run(const std::filesystem::path& dir, const std::string& node_id) {
  facet::Registry registry;
  registry.add<Sink>();
  facet::ValidatedGraph graph;
  graph.name = "sinks";
  facet::ValidatedNode node;
  node.id = node_id;
  node.stage = registry.find(Sink::spec().name());
  node.params = node.stage->spec.default_params();
  node.params.set("dir", dir.string());
  node.inputs.resize(node.stage->spec.inputs().size());
  graph.nodes.push_back(std::move(node));
  facet::SequentialExecutor executor(graph);
  facet::RunOptions options;
  options.max_frames = 1;
  try {
    executor.run(options);
  } catch (const facet::RunError& e) {
    return e.what();
  }
  return "no error";
}

TEST(OverlayAndCloudSinks, UnwritableFolderNamesNodeAndFolder) {
  TempDir dir;
  write_text(dir / "occupied", "a file, not a folder");
  const auto folder = dir / "occupied/overlay";
  const std::string overlay = open_error_of_a_run<facet::io::OverlaySink>(folder, "overlay_out");
  EXPECT_NE(overlay.find("node 'overlay_out' (io.overlay)"), std::string::npos) << overlay;
  const std::string folder_named = "cannot create output folder '" + folder.string() + "'";
  EXPECT_NE(overlay.find(folder_named), std::string::npos) << overlay;
}

TEST(OverlayAndCloudSinks, SpecsDocumentEveryPortAndParameter) {
  for (const facet::StageSpec& spec : {facet::io::OverlaySink::spec()}) {
    SCOPED_TRACE(spec.name());
    EXPECT_TRUE(spec.outputs().empty());
    EXPECT_EQ(spec.concurrency(), facet::Concurrency::serial);
    EXPECT_TRUE(spec.find_param("dir")->options.required);
    for (const auto& port : spec.inputs())
      EXPECT_FALSE(port.doc.empty()) << port.name;
    for (const auto& param : spec.params())
      EXPECT_FALSE(param.doc.empty()) << param.name;
  }
  EXPECT_FALSE(facet::io::OverlaySink::spec().find_input("edges")->required);
  EXPECT_TRUE(facet::io::OverlaySink::spec().find_input("labels")->required);
}

}  // namespace
