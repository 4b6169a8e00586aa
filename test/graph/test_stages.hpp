#pragma once
// Tiny in-process stages for the graph tests: enough ports, types and parameter kinds to exercise
// every validation rule, without loading a plugin. They never run.

#include <facet/framework/registry.hpp>
#include <facet/stage.hpp>
#include <facet/types/images.hpp>

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

inline void add_test_stages(Registry& registry) {
  registry.add<FramesSource>();
  registry.add<MedianFilter>();
  registry.add<CrossNormals>();
  registry.add<PcaNormals>();
  registry.add<PointNormals>();
  registry.add<AngleEdges>();
  registry.add<DepthWriter>();
}

}  // namespace facet::graph_test
