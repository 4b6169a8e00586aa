#pragma once
// Small graphs for executor tests, built straight from registered stages without a YAML file, and
// the frames their test sources emit.

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "facet/framework/registry.hpp"
#include "facet/framework/validated_graph.hpp"
#include "facet/stage.hpp"
#include "facet/types/images.hpp"

namespace facet::test {

struct NodeDesc {
  std::string id;
  std::string stage;
  std::map<std::string, ParamValue> params;
  std::vector<std::string> inputs;  // nodes feeding the input ports, in port order
};

// Nodes must be listed producers first (the executors take the graph's order as given).
inline ValidatedGraph make_graph(const Registry& registry, const std::vector<NodeDesc>& nodes) {
  ValidatedGraph g;
  g.name = "test";
  std::map<std::string, std::size_t> index;
  for (const auto& desc : nodes) {
    ValidatedNode node;
    node.id = desc.id;
    node.stage = registry.find(desc.stage);
    EXPECT_NE(node.stage, nullptr) << desc.stage;
    node.params = node.stage->spec.default_params();
    for (const auto& [name, value] : desc.params)
      node.params.set(name, value);
    for (const auto& from : desc.inputs)
      node.inputs.push_back(Connection{index.at(from), 0});
    node.inputs.resize(node.stage->spec.inputs().size());
    index[desc.id] = g.nodes.size();
    g.nodes.push_back(std::move(node));
  }
  return g;
}

// What a test source emits for frame i of `stream_frames`: a 4x4 depth image holding i + 1, stem
// "f<i>", or nothing every `gap_every`-th frame (0 = never), so that consumers with a required
// input are skipped.
inline void emit_counting_frame(ProcessContext& ctx, std::int64_t gap_every,
                                std::int64_t stream_frames) {
  if (gap_every > 0 && (ctx.frame_index() + 1) % gap_every == 0) return;
  DepthImage image;
  image.frame.index = ctx.frame_index();
  image.frame.stem = "f" + std::to_string(ctx.frame_index());
  image.frame.stream_frames = stream_frames;
  image.depth = cv::Mat(4, 4, CV_16UC1, cv::Scalar(static_cast<double>(ctx.frame_index() + 1)));
  ctx.output("depth", std::move(image));
}

}  // namespace facet::test
