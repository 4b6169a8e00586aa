#pragma once
// Runs io.synthetic as a unit (StageRunner) and collects the frames it generates.

#include <cstdint>
#include <map>
#include <opencv2/core.hpp>
#include <set>
#include <string>
#include <vector>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "synthetic/synthetic_source.hpp"

namespace facet::test {

using SyntheticRunner = testing::StageRunner<synthetic::SyntheticSource>;
using ParamMap = std::map<std::string, ParamValue>;

struct SyntheticFrame {
  DepthImage depth;
  LabelImage labels;
};

// The first `count` frames of io.synthetic with `params`.
inline std::vector<SyntheticFrame> generate(const ParamMap& params, int count) {
  SyntheticRunner runner(params);
  std::vector<SyntheticFrame> frames;
  for (int i = 0; i < count; ++i) {
    runner.run();
    if (runner.at_end_of_stream()) break;
    frames.push_back({runner.output<DepthImage>("depth"), runner.output<LabelImage>("labels")});
  }
  return frames;
}

inline SyntheticFrame first_frame(const ParamMap& params) {
  return generate(params, 1).at(0);
}

// Pixel count of every non-zero label.
inline std::map<std::int32_t, int> label_pixels(const cv::Mat& labels) {
  std::map<std::int32_t, int> counts;
  for (int v = 0; v < labels.rows; ++v) {
    for (int u = 0; u < labels.cols; ++u) {
      if (const auto id = labels.at<std::int32_t>(v, u); id != 0) ++counts[id];
    }
  }
  return counts;
}

inline bool same_image(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  cv::Mat difference;
  cv::compare(a, b, difference, cv::CMP_NE);
  return cv::countNonZero(difference.reshape(1)) == 0;
}

}  // namespace facet::test
