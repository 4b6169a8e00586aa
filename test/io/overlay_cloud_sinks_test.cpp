// io.overlay and io.cloud: the picture and the point cloud of a segmented frame, and the palette
// both take their colours from.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <set>
#include <sstream>
#include <tuple>
#include <type_traits>

#include "facet/framework/executor.hpp"
#include "facet/framework/registry.hpp"
#include "facet/testing/reverse_runner.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "io/cloud_sink.hpp"
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

TEST(OverlaySink, RowsDrawnInBandsGiveTheSamePicture) {
  // 640 x 480 with segments and borders crossing every band boundary.
  cv::Mat depth(480, 640, CV_16UC1);
  cv::randu(depth, 600, 1400);
  cv::Mat labels = cv::Mat::zeros(depth.size(), CV_32SC1);
  for (int i = 0; i < 12; ++i)
    cv::circle(labels, cv::Point(50 * i + 30, 40 * i + 20), 45, cv::Scalar(i + 1), -1);
  cv::Mat edges = cv::Mat::zeros(depth.size(), CV_8UC1);
  edges.row(100).setTo(255);
  facet::io::OverlayStyle style;
  style.draw_edges = true;
  const cv::Mat whole = facet::io::render_overlay(depth, labels, edges, style);
  facet::testing::ReverseRunner runner(4);
  const cv::Mat banded = facet::io::render_overlay(depth, labels, edges, style, &runner);
  EXPECT_EQ(runner.runs(), 1) << "the picture was not split";
  EXPECT_EQ(cv::norm(whole, banded, cv::NORM_INF), 0.0);
}

TEST(OverlaySink, DrawsTheEdgeMaskWhenConnectedAndAsked) {
  TempDir dir;
  const OverlayScene scene = overlay_scene("e");
  EdgeImage edges;
  edges.score = cv::Mat(8, 12, CV_32FC1, cv::Scalar(1.0));
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

  // A colour is a structured parameter: refused where values are validated (as facet validate
  // does, with the graph's file:line:col), before the stage is built.
  try {
    OverlayRunner bad({{"dir", dir.path().string()}, {"edge_colour", std::string("red")}});
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    for (const char* part : {"edge_colour", "'red'", "#rrggbb"}) {
      EXPECT_NE(message.find(part), std::string::npos) << message;
    }
  }
  expect_stage_error(
      [&] {
        OverlayRunner bad({{"dir", dir.path().string()}, {"near_m", 2.0}, {"far_m", 1.0}});
      },
      {"far_m", "near_m"});
}

// ---------------------------------------------------------------------------------------------
// io.cloud

// A PLY file as read back by a small independent reader: header fields and vertex rows.
struct PlyVertex {
  float x = 0, y = 0, z = 0;
  Rgb colour;
  std::uint32_t label = 0;
};

struct PlyFile {
  std::string format;
  std::int64_t declared_vertices = -1;
  std::vector<std::string> properties;  // "float x", ...
  std::vector<PlyVertex> vertices;
  bool trailing_bytes = false;
};

template <class T>
T read_le(const std::string& bytes, std::size_t& at) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    value |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes.at(at + i))) << (8 * i);
  at += sizeof(T);
  if constexpr (std::is_same_v<T, float>) {
    return std::bit_cast<float>(value);
  } else {
    return static_cast<T>(value);
  }
}

PlyFile read_ply(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  PlyFile ply;
  const std::string end = "end_header\n";
  const auto header_end = bytes.find(end);
  EXPECT_NE(header_end, std::string::npos) << file;
  if (header_end == std::string::npos) return ply;
  std::istringstream header(bytes.substr(0, header_end));
  std::string line;
  std::getline(header, line);
  EXPECT_EQ(line, "ply");
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      words >> ply.format;
    } else if (keyword == "element") {
      std::string name;
      words >> name >> ply.declared_vertices;
      EXPECT_EQ(name, "vertex");
    } else if (keyword == "property") {
      ply.properties.push_back(line.substr(9));
    }
  }
  std::size_t at = header_end + end.size();
  if (ply.format == "binary_little_endian") {
    for (std::int64_t i = 0; i < ply.declared_vertices && at + 19 <= bytes.size(); ++i) {
      PlyVertex v;
      v.x = read_le<float>(bytes, at);
      v.y = read_le<float>(bytes, at);
      v.z = read_le<float>(bytes, at);
      v.colour.r = read_le<std::uint8_t>(bytes, at);
      v.colour.g = read_le<std::uint8_t>(bytes, at);
      v.colour.b = read_le<std::uint8_t>(bytes, at);
      v.label = read_le<std::uint32_t>(bytes, at);
      ply.vertices.push_back(v);
    }
    ply.trailing_bytes = at != bytes.size();
  } else {
    std::istringstream body(bytes.substr(at));
    PlyVertex v;
    unsigned r = 0, g = 0, b = 0;
    while (body >> v.x >> v.y >> v.z >> r >> g >> b >> v.label) {
      v.colour = Rgb{static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g),
                     static_cast<std::uint8_t>(b)};
      ply.vertices.push_back(v);
    }
    ply.trailing_bytes = !body.eof();
  }
  return ply;
}

// 4x3 points with three NaN points (one with only z NaN); labels 0, 2 and 5.
struct CloudScene {
  PointImage points;
  LabelImage labels;
};

CloudScene cloud_scene(const std::string& stem) {
  CloudScene scene;
  scene.points.frame.stem = stem;
  scene.points.points = cv::Mat(3, 4, CV_32FC3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      scene.points.points.at<cv::Vec3f>(y, x) =
          cv::Vec3f(0.001F * static_cast<float>(x) - 0.25F, -0.1F / 3.0F * static_cast<float>(y),
                    0.8F + 0.0123F * static_cast<float>(x + 4 * y));
    }
  }
  scene.points.points.at<cv::Vec3f>(0, 1) = cv::Vec3f(kNaN, kNaN, kNaN);
  scene.points.points.at<cv::Vec3f>(1, 2) = cv::Vec3f(kNaN, kNaN, kNaN);
  scene.points.points.at<cv::Vec3f>(2, 0)[2] = kNaN;
  scene.labels.frame.stem = stem;
  scene.labels.labels = (cv::Mat_<std::int32_t>(3, 4) << 0, 2, 2, 0,  //
                         5, 5, 2, 0,                                  //
                         5, 5, 5, 2);
  scene.labels.count = 5;
  return scene;
}

// The vertices io.cloud should write for `scene`, in row-major order.
std::vector<PlyVertex> expected_vertices(const CloudScene& scene, bool labelled_only) {
  std::vector<PlyVertex> expected;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      const cv::Vec3f p = scene.points.points.at<cv::Vec3f>(y, x);
      const auto label = static_cast<std::uint32_t>(scene.labels.labels.at<std::int32_t>(y, x));
      if (std::isnan(p[0]) || std::isnan(p[1]) || std::isnan(p[2])) continue;
      if (labelled_only && label == 0) continue;
      const Rgb colour = label == 0 ? Rgb{170, 170, 170} : label_colour(label);
      expected.push_back({p[0], p[1], p[2], colour, label});
    }
  }
  return expected;
}

void expect_same_vertices(const std::vector<PlyVertex>& actual,
                          const std::vector<PlyVertex>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    SCOPED_TRACE("vertex " + std::to_string(i));
    // Both encodings are exact: binary by construction, ascii by shortest round-trip text.
    EXPECT_EQ(actual[i].x, expected[i].x);
    EXPECT_EQ(actual[i].y, expected[i].y);
    EXPECT_EQ(actual[i].z, expected[i].z);
    EXPECT_EQ(actual[i].colour, expected[i].colour);
    EXPECT_EQ(actual[i].label, expected[i].label);
  }
}

using CloudRunner = facet::testing::StageRunner<facet::io::CloudSink>;

TEST(CloudSink, BinaryPlyHasTheValidPointsWithLabelsAndColours) {
  TempDir dir;
  CloudRunner sink({{"dir", (dir / "cloud").string()}});
  const CloudScene scene = cloud_scene("learn5");
  sink.set_input("points", Packet::make(scene.points));
  sink.set_input("labels", Packet::make(scene.labels));
  sink.run();
  const PlyFile ply = read_ply(dir / "cloud/learn5.ply");
  EXPECT_EQ(ply.format, "binary_little_endian");
  EXPECT_EQ(ply.declared_vertices, 9);  // 12 pixels, 3 of them NaN
  const std::vector<std::string> properties{"float x",     "float y",    "float z",   "uchar red",
                                            "uchar green", "uchar blue", "uint label"};
  EXPECT_EQ(ply.properties, properties);
  EXPECT_FALSE(ply.trailing_bytes);
  expect_same_vertices(ply.vertices, expected_vertices(scene, false));
  ASSERT_EQ(sink.metrics().size(), 1U);
  EXPECT_EQ(sink.metrics()[0].name, "points");
  EXPECT_EQ(sink.metrics()[0].value, 9.0);
}

TEST(CloudSink, AsciiPlyReadsBackTheSame) {
  TempDir dir;
  CloudRunner sink({{"dir", dir.path().string()}, {"format", std::string("ascii")}});
  const CloudScene scene = cloud_scene("t");
  sink.set_input("points", Packet::make(scene.points));
  sink.set_input("labels", Packet::make(scene.labels));
  sink.run();
  const PlyFile ply = read_ply(dir / "t.ply");
  EXPECT_EQ(ply.format, "ascii");
  EXPECT_EQ(ply.declared_vertices, 9);
  EXPECT_FALSE(ply.trailing_bytes);
  expect_same_vertices(ply.vertices, expected_vertices(scene, false));
}

TEST(CloudSink, LabelledOnlyAndUnconnectedLabels) {
  TempDir dir;
  const CloudScene scene = cloud_scene("s");
  {
    CloudRunner sink({{"dir", (dir / "labelled").string()}, {"labelled_only", true}});
    sink.set_input("points", Packet::make(scene.points));
    sink.set_input("labels", Packet::make(scene.labels));
    sink.run();
    const PlyFile ply = read_ply(dir / "labelled/s.ply");
    EXPECT_EQ(ply.declared_vertices, 6);
    expect_same_vertices(ply.vertices, expected_vertices(scene, true));
  }
  {
    CloudRunner sink({{"dir", (dir / "plain").string()}});
    sink.set_input("points", Packet::make(scene.points));
    sink.run();
    const PlyFile ply = read_ply(dir / "plain/s.ply");
    EXPECT_EQ(ply.declared_vertices, 9);
    for (const PlyVertex& v : ply.vertices) {
      EXPECT_EQ(v.label, 0U);
      EXPECT_EQ(v.colour, (Rgb{170, 170, 170}));
    }
  }
}

TEST(CloudSink, NoValidPointGivesAnEmptyButWellFormedFile) {
  TempDir dir;
  CloudRunner sink({{"dir", dir.path().string()}});
  PointImage points = with_frame(PointImage{}, "none");
  points.points = cv::Mat(2, 2, CV_32FC3, cv::Scalar(kNaN, kNaN, kNaN));
  sink.set_input("points", Packet::make(points));
  sink.run();
  const PlyFile ply = read_ply(dir / "none.ply");
  EXPECT_EQ(ply.declared_vertices, 0);
  EXPECT_TRUE(ply.vertices.empty());
  EXPECT_FALSE(ply.trailing_bytes);
}

// PLY labels are unsigned and points are CV_32FC3: what breaks the types' formats never reaches
// the sink (a graph refuses it at the producer's output, a test at set_input).
TEST(CloudSink, NegativeLabelsAndWrongTypesNeverReachIt) {
  TempDir dir;
  CloudRunner sink({{"dir", dir.path().string()}});
  CloudScene scene = cloud_scene("neg");
  scene.labels.labels.at<std::int32_t>(1, 1) = -4;
  EXPECT_THROW(sink.set_input("labels", Packet::make(scene.labels)), std::invalid_argument);

  PointImage depth_like = with_frame(PointImage{}, "flat");
  depth_like.points = cv::Mat(3, 4, CV_32FC1, cv::Scalar(1.0));
  EXPECT_THROW(sink.set_input("points", Packet::make(depth_like)), std::invalid_argument);
}

TEST(CloudSink, LabelsOfAnotherSizeAreAnErrorNamingBothPorts) {
  TempDir dir;
  CloudRunner sink({{"dir", dir.path().string()}});
  CloudScene scene = cloud_scene("small");
  sink.set_input("points", Packet::make(scene.points));
  scene.labels.labels = scene.labels.labels(cv::Rect(0, 0, 2, 2)).clone();
  sink.set_input("labels", Packet::make(scene.labels));
  expect_stage_error([&] { sink.run(); }, {"'points' (4x3)", "'labels' (2x2)"});
}

TEST(OverlayAndCloudSinks, AFileThatCannotBeWrittenIsAnErrorNamingIt) {
  TempDir dir;
  std::filesystem::create_directories(dir / "x.png");  // a folder where the file should go
  std::filesystem::create_directories(dir / "x.ply");
  OverlayRunner overlay({{"dir", dir.path().string()}});
  const OverlayScene scene = overlay_scene("x");
  overlay.set_input("depth", Packet::make(scene.depth));
  overlay.set_input("labels", Packet::make(scene.labels));
  expect_stage_error([&] { overlay.run(); }, {"cannot write", (dir / "x.png").string()});

  CloudRunner cloud({{"dir", dir.path().string()}});
  cloud.set_input("points", Packet::make(cloud_scene("x").points));
  expect_stage_error([&] { cloud.run(); },
                     {"cannot write", (dir / "x.ply").string(), "Is a directory"});
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
  const std::string cloud = open_error_of_a_run<facet::io::CloudSink>(folder, "cloud_out");
  EXPECT_NE(overlay.find("node 'overlay_out' (io.overlay)"), std::string::npos) << overlay;
  EXPECT_NE(cloud.find("node 'cloud_out' (io.cloud)"), std::string::npos) << cloud;
  const std::string folder_named = "cannot create output folder '" + folder.string() + "'";
  EXPECT_NE(overlay.find(folder_named), std::string::npos) << overlay;
  EXPECT_NE(cloud.find(folder_named), std::string::npos) << cloud;
}

TEST(OverlayAndCloudSinks, SpecsDocumentEveryPortAndParameter) {
  for (const facet::StageSpec& spec :
       {facet::io::OverlaySink::spec(), facet::io::CloudSink::spec()}) {
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
  EXPECT_FALSE(facet::io::CloudSink::spec().find_input("labels")->required);
}

}  // namespace
