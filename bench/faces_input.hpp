#pragma once
// The inputs that graphs/faces.yaml and graphs/tabletop.yaml give their region-growing and object
// stages, made by the same stages with the same settings from a bundled mOSD frame: 3x3 median,
// points, image-space cross-product normals on Kinect disparity (r = 2, the paper's triangle),
// edges.max over 3 pixels at 0.85. For benchmarks that time one later stage on real input.

#include <filesystem>
#include <string>

#include "bundled_frames.hpp"
#include "convert/points_stage.hpp"
#include "edges/edges_max.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "filter/median_filter.hpp"
#include "normals/cross_stage.hpp"

namespace facet::bench {

struct FacesInput {
  Packet points;  // PointImage
  Packet edges;   // EdgeImage
};

inline FacesInput faces_input(const std::string& stem) {
  using testing::StageRunner;
  const auto mosd = std::filesystem::path(FACET_SOURCE_DIR) / "data" / "mosd";
  DepthImage depth = test::bundled_mosd_frame(mosd, stem);
  StageRunner<filters::MedianFilter> median({{"size", std::int64_t{3}}});
  median.set_input("depth", Packet::make(std::move(depth)));
  median.run();
  StageRunner<convert::PointsStage> points;
  points.set_input("depth", median.output_packet("depth"));
  points.run();
  StageRunner<normals::CrossStage> normals({{"space", std::string("image")},
                                            {"image_depth", std::string("disparity")},
                                            {"radius", std::int64_t{2}},
                                            {"triangle", std::string("paper")}});
  normals.set_input("depth", median.output_packet("depth"));
  normals.run();
  StageRunner<edges::MaxNormalEdges> edges({{"pixels", std::int64_t{3}}, {"threshold", 0.85}});
  edges.set_input("normals", normals.output_packet("normals"));
  edges.run();
  return {points.output_packet("points"), edges.output_packet("edges")};
}

}  // namespace facet::bench
