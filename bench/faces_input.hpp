#pragma once
// The inputs that graphs/faces.yaml and graphs/tabletop.yaml give their region-growing and object
// stages, made by the same stages with the same settings from a bundled mOSD frame: 3x3 median,
// points, image-space cross-product normals on Kinect disparity (r = 2, the paper's triangle),
// edges.max over 3 pixels at 0.85. For benchmarks that time one later stage on real input.

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

#include "convert/points_stage.hpp"
#include "edges/edges_max.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "filters/median_filter.hpp"
#include "normals/cross_stage.hpp"

namespace facet::bench {

struct FacesInput {
  Packet points;  // PointImage
  Packet edges;   // EdgeImage
};

inline FacesInput faces_input(const std::string& stem) {
  using testing::StageRunner;
  const auto mosd = std::filesystem::path(FACET_SOURCE_DIR) / "data" / "mosd";
  DepthImage depth;
  depth.depth = cv::imread((mosd / "depth" / (stem + ".png")).string(), cv::IMREAD_UNCHANGED);
  if (depth.depth.type() != CV_16UC1) throw std::runtime_error("cannot read " + stem);
  // The bundled mOSD intrinsics (Kinect, 640x480).
  depth.camera = {525.0, 525.0, 319.5, 239.5, depth.depth.cols, depth.depth.rows};
  depth.frame.stem = stem;
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
