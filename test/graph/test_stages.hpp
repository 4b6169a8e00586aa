#pragma once
// Tiny in-process stages for the graph tests: enough ports, types and parameter kinds to exercise
// every validation rule, without loading a plugin. They never run.

#include <charconv>
#include <facet/contract.hpp>
#include <facet/framework/registry.hpp>
#include <facet/stage.hpp>
#include <facet/types/images.hpp>
#include <string>
#include <variant>

namespace facet::graph_test {

// A structured parameter value, written "WxH" (whole millimetres, both positive).
struct Extent {
  int width_mm = 0;
  int height_mm = 0;
};

}  // namespace facet::graph_test

template <>
struct facet::ParamTraits<facet::graph_test::Extent> {
  static std::variant<graph_test::Extent, std::string> parse(std::string_view text) {
    const auto x = text.find('x');
    graph_test::Extent extent;
    const auto width = text.substr(0, x);
    const auto height = x == std::string_view::npos ? std::string_view() : text.substr(x + 1);
    const auto read = [](std::string_view part, int& value) {
      const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
      return ec == std::errc() && end == part.data() + part.size() && value > 0;
    };
    if (x == std::string_view::npos || !read(width, extent.width_mm) ||
        !read(height, extent.height_mm)) {
      return "expected 'WxH' in whole millimetres, e.g. '300x200', got '" + std::string(text) + "'";
    }
    return extent;
  }
  static std::string format(const graph_test::Extent& extent) {
    return std::to_string(extent.width_mm) + "x" + std::to_string(extent.height_mm);
  }
};

namespace facet::graph_test {

class NoOpStage : public Stage {
 public:
  explicit NoOpStage(const Params& /*params*/) {}
  void process(ProcessContext& /*ctx*/) override {}
};

struct FramesSource final : NoOpStage {
  using NoOpStage::NoOpStage;
  static StageSpec spec() {
    StageSpec spec("io.frames", "Reads recorded depth frames.");
    spec.output<DepthImage>("depth", "Depth image.");
    spec.param("path", "", "Directory of the recording.", {.required = true});
    spec.param("fps", 30.0, "Frames per second.", {.unit = "Hz", .min = 0.0});
    spec.param("loop", false, "Start again at the end.");
    return spec;
  }
};

struct MedianFilter final : NoOpStage {
  using NoOpStage::NoOpStage;
  static StageSpec spec() {
    StageSpec spec("filter.median", "Median filter.");
    spec.input<DepthImage>("depth", "Depth image.");
    spec.output<DepthImage>("depth", "Filtered depth image.");
    spec.param("size", 3, "Window side.",
               {.unit = "px", .choices = {std::int64_t{3}, std::int64_t{5}}});
    return spec;
  }
};

struct CrossNormals final : NoOpStage {
  using NoOpStage::NoOpStage;
  static StageSpec spec() {
    StageSpec spec("normals.cross", "Normals from cross products.");
    spec.input<DepthImage>("depth", "Depth image.");
    spec.output<NormalImage>("normals", "Unit normals.");
    spec.param("radius", 2, "Neighbour distance.", {.unit = "px", .min = 1.0, .max = 10.0});
    spec.param("max_jump", 0.05, "Largest depth step.", {.unit = "m", .min = 0.0});
    return spec;
  }
};

struct PcaNormals final : NoOpStage {
  using NoOpStage::NoOpStage;
  static StageSpec spec() {
    StageSpec spec("normals.pca", "Normals from local PCA.");
    spec.input<DepthImage>("depth", "Depth image.");
    spec.output<NormalImage>("normals", "Unit normals.");
    spec.param("window", 5, "Window side.", {.unit = "px", .min = 3.0});
    return spec;
  }
};

// Same parameter as CrossNormals but different ports: a replacement that must be refused.
struct PointNormals final : NoOpStage {
  using NoOpStage::NoOpStage;
  static StageSpec spec() {
    StageSpec spec("normals.points", "Normals from a point image.");
    spec.input<PointImage>("points", "Points.");
    spec.output<NormalImage>("normals", "Unit normals.");
    return spec;
  }
};

struct AngleEdges final : NoOpStage {
  using NoOpStage::NoOpStage;
  static StageSpec spec() {
    StageSpec spec("edges.angle", "Edges where normals turn.");
    spec.input<NormalImage>("normals", "Unit normals.");
    spec.optional_input<DepthImage>("depth", "Depth, to find jump edges too.");
    spec.output<EdgeImage>("edges", "Edge score and mask.");
    spec.param("threshold", 0.5, "Score below which a pixel is an edge.", {.min = 0.0, .max = 1.0});
    spec.param("mode", "angle", "What to compare.",
               {.choices = {std::string("angle"), std::string("dot")}});
    return spec;
  }
};

struct DepthWriter final : NoOpStage {
  using NoOpStage::NoOpStage;
  static StageSpec spec() {
    StageSpec spec("io.depth", "Writes depth images.");
    spec.input<DepthImage>("depth", "Depth image.");
    spec.param("dir", "", "Output directory.", {.required = true});
    return spec;
  }
};

// Declared with typed contracts, and a structured parameter whose parser validation runs.
inline const In<DepthImage> kCropDepth{"depth", "Depth image."};
inline const Out<DepthImage> kCropped{"depth", "The cropped depth image."};
inline const Param<Extent> kCropExtent{"extent", Extent{640, 480}, "Size of the crop, 'WxH'."};

class CropStage final : public NoOpStage {
 public:
  using NoOpStage::NoOpStage;
  static StageSpec spec() {
    StageSpec spec("filter.crop", "Crops the depth image.");
    return spec.declare(kCropDepth, kCropped, kCropExtent);
  }
};

inline void add_test_stages(Registry& registry) {
  registry.add<CropStage>();
  registry.add<FramesSource>();
  registry.add<MedianFilter>();
  registry.add<CrossNormals>();
  registry.add<PcaNormals>();
  registry.add<PointNormals>();
  registry.add<AngleEdges>();
  registry.add<DepthWriter>();
}

}  // namespace facet::graph_test
