#pragma once
// The whole tabletop graph (graphs/tabletop.yaml) on a dataset a test writes itself: the graph is
// loaded and run through the framework with the plugins of this build, as `facet run` does, and
// what it wrote for each frame (labels PNG, objects JSON) and reported (warnings, errors) is read
// back for the test to judge.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bundled_plugins.hpp"
#include "facet/framework/diagnostics.hpp"
#include "facet/framework/executor.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/plugin_loader.hpp"
#include "facet/framework/registry.hpp"
#include "facet/framework/validated_graph.hpp"
#include "facet/types/frame.hpp"
#include "temp_dir.hpp"

namespace facet::test {

// A dataset folder (docs/data-formats.md): intrinsics.yaml and depth/<stem>.png, plus the folder
// the run writes its results to.
class Dataset {
 public:
  explicit Dataset(const CameraIntrinsics& camera) : camera_(camera) {
    std::filesystem::create_directories(input() / "depth");
    std::ofstream(input() / "intrinsics.yaml")
        << "fx: " << camera.fx << "\nfy: " << camera.fy << "\ncx: " << camera.cx
        << "\ncy: " << camera.cy << "\nwidth: " << camera.width << "\nheight: " << camera.height
        << "\n";
  }

  // Writes depth/<stem>.png; frames run in natural order of their stems.
  void add(const std::string& stem, const cv::Mat& depth) {
    const auto file = input() / "depth" / (stem + ".png");
    ASSERT_TRUE(cv::imwrite(file.string(), depth)) << file;
    stems_.push_back(stem);
  }

  const CameraIntrinsics& camera() const { return camera_; }
  std::filesystem::path input() const { return dir_.path() / "data"; }
  std::filesystem::path output() const { return dir_.path() / "out"; }
  const std::vector<std::string>& stems() const { return stems_; }

 private:
  TempDir dir_{"facet-bad-input"};
  CameraIntrinsics camera_;
  std::vector<std::string> stems_;
};

// What one frame's run left behind.
struct FrameResult {
  std::string stem;
  cv::Mat labels;                     // OUT/labels/<stem>.png as read (CV_16UC1 expected)
  std::string json;                   // OUT/objects/<stem>.json
  std::vector<std::int64_t> ids;      // object ids listed in the JSON, in order
  std::vector<std::string> warnings;  // stage warnings of this frame

  std::size_t objects() const { return ids.size(); }
  // The warnings of this frame, one per line, for failure messages.
  std::string warning_text() const {
    std::string text;
    for (const auto& warning : warnings)
      text += warning + "\n";
    return text;
  }
  bool warned(const std::string& part) const {
    return std::any_of(warnings.begin(), warnings.end(), [&](const std::string& warning) {
      return warning.find(part) != std::string::npos;
    });
  }
};

struct TabletopRun {
  std::string error;  // the RunError (or graph diagnostics) when the run did not complete
  std::int64_t frames = 0;
  std::vector<std::string> warnings;  // as the CLI prints them: "warning: node 'n', frame i: ..."
  std::vector<FrameResult> results;   // per frame of the dataset, in order
  double seconds = 0.0;

  bool completed() const { return error.empty(); }
  const FrameResult& frame(const std::string& stem) const {
    for (const auto& result : results) {
      if (result.stem == stem) return result;
    }
    static const FrameResult none;
    ADD_FAILURE() << "no result for frame '" << stem << "'";
    return none;
  }
};

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::vector<std::int64_t> object_ids(const std::string& json) {
  std::vector<std::int64_t> ids;
  static const std::regex id(R"re("id": (-?[0-9]+))re");
  for (auto it = std::sregex_iterator(json.begin(), json.end(), id); it != std::sregex_iterator();
       ++it) {
    ids.push_back(std::stoll((*it)[1].str()));
  }
  return ids;
}

// Runs graphs/tabletop.yaml on `data` (graph params input and output), with optional node
// parameter overrides (--set node.param=value).
inline TabletopRun run_tabletop(
    const Dataset& data, const std::vector<std::pair<std::string, std::string>>& sets = {},
    const std::string& variant = "",
    const std::vector<std::pair<std::string, std::string>>& params = {}) {
  TabletopRun run;
  const auto start = std::chrono::steady_clock::now();
  Diagnostics diagnostics;
  LoadOptions options;
  options.params = {{"input", data.input().string()}, {"output", data.output().string()}};
  options.params.insert(params.begin(), params.end());
  options.sets = sets;
  options.variant = variant;
  const GraphSpec spec = load_graph_file(
      std::filesystem::path(FACET_SOURCE_DIR) / "graphs/tabletop.yaml", options, diagnostics);
  const ValidatedGraph graph = validate_graph(spec, bundled_plugins(), diagnostics);
  if (diagnostics.has_errors()) {
    run.error = diagnostics.str();
    return run;
  }
  try {
    SequentialExecutor executor(graph);
    RunOptions run_options;
    run_options.on_warning = [&](const std::string& message) { run.warnings.push_back(message); };
    run.frames = executor.run(run_options).frames;
  } catch (const RunError& error) {
    run.error = error.what();
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Warnings name the frame by its position in the stream, which the objects JSON records.
  static const std::regex index_key(R"re("index": ([0-9]+))re");
  for (const auto& stem : data.stems()) {
    FrameResult result;
    result.stem = stem;
    const auto labels = data.output() / "labels" / (stem + ".png");
    if (std::filesystem::exists(labels))
      result.labels = cv::imread(labels.string(), cv::IMREAD_UNCHANGED);
    result.json = read_text(data.output() / "objects" / (stem + ".json"));
    result.ids = object_ids(result.json);
    if (std::smatch index; std::regex_search(result.json, index, index_key)) {
      const std::string tag = ", frame " + index[1].str() + ": ";
      for (const auto& warning : run.warnings) {
        if (warning.find(tag) != std::string::npos) result.warnings.push_back(warning);
      }
    }
    run.results.push_back(std::move(result));
  }
  return run;
}

// Every frame's outputs are there and agree: a 16-bit label image of the input's size, an object
// list naming exactly the ids the image holds, and no number in it that is not finite (io.objects
// writes those as null; only a missing superquadric, missing bounds or a missing support plane's
// equation may be null, never the camera).
inline void expect_complete_output(const FrameResult& frame, const CameraIntrinsics& camera) {
  SCOPED_TRACE("frame " + frame.stem);
  ASSERT_FALSE(frame.labels.empty()) << "no labels PNG";
  EXPECT_EQ(frame.labels.type(), CV_16UC1);
  EXPECT_EQ(frame.labels.cols, camera.width);
  EXPECT_EQ(frame.labels.rows, camera.height);
  ASSERT_FALSE(frame.json.empty()) << "no objects JSON";
  EXPECT_NE(frame.json.find("\"stem\": \"" + frame.stem + "\""), std::string::npos) << frame.json;

  std::string lower = frame.json;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  EXPECT_EQ(lower.find("nan"), std::string::npos) << frame.json;
  EXPECT_EQ(lower.find("inf"), std::string::npos) << frame.json;
  std::istringstream lines(frame.json);
  for (std::string line; std::getline(lines, line);) {
    if (line.find("null") == std::string::npos) continue;
    EXPECT_TRUE(line.find("\"superquadric\": null") != std::string::npos ||
                line.find("\"bounds_m\": null") != std::string::npos ||
                line.find("\"support_plane_equation\": null") != std::string::npos)
        << "a non-finite number: " << line;
  }

  std::set<std::int64_t> in_image;
  if (frame.labels.type() == CV_16UC1) {
    for (int v = 0; v < frame.labels.rows; ++v) {
      for (int u = 0; u < frame.labels.cols; ++u) {
        if (const auto id = frame.labels.at<std::uint16_t>(v, u); id != 0) in_image.insert(id);
      }
    }
  }
  const std::set<std::int64_t> in_list(frame.ids.begin(), frame.ids.end());
  EXPECT_EQ(in_list.size(), frame.ids.size()) << "an id listed twice";
  EXPECT_EQ(in_image, in_list) << "the labels PNG and the objects JSON disagree";
}

}  // namespace facet::test
