#pragma once
// facet::Pipeline: a graph file run inside a host program, one frame per call.
//
// A graph declares what a host feeds and reads (docs/embedding.md):
//
//   inputs:  {depth: source.depth}       the host's depth image replaces the source's output;
//                                        the node `source` is then not run at all
//   outputs: {labels: objects.objects, objects: shapes.objects}
//
// Only the nodes the outputs need are run, so the file sinks of a graph written for the command
// line stay off unless PipelineOptions::run_sinks asks for them. A graph without `inputs:` is
// pulled from its own source (a folder, a camera): process() with no inputs gives the next frame.
//
//   facet::Pipeline seg("graphs/tabletop.yaml");
//   facet::DepthImage depth;  // CV_16UC1 mm or CV_32FC1 m, with its camera intrinsics
//   ...
//   facet::FrameResult out = seg.process({{"depth", facet::Packet::make(depth)}});
//   const auto& labels = out.outputs.at("labels").get_if<facet::LabelImage>()->labels;
//
// A Pipeline is used from one thread at a time; two Pipelines run in parallel on two threads.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "facet/packet.hpp"

namespace facet {

// How a graph is loaded: the command line's --param, --set, --variant and --plugin-path.
struct PipelineOptions {
  std::map<std::string, std::string> params;              // graph params, name -> value
  std::vector<std::pair<std::string, std::string>> sets;  // "node.param" -> value, in order
  std::string variant;                                    // empty: none
  // Searched before FACET_PLUGIN_PATH, the graph's own `plugins.paths` and the bundled plugins.
  std::vector<std::filesystem::path> plugin_paths;
  // Also run the nodes that feed no graph output (the file sinks: labels, objects, overlays).
  bool run_sinks = false;
  // Keep frame-sized buffers mapped between frames (two glibc malloc options, process-wide, as
  // the `facet` CLI sets them): with glibc's defaults each frame's 1-4 MB images are mapped and
  // unmapped again, which made a tabletop frame 28 ms instead of 17.5 ms (docs/performance.md).
  bool keep_frame_buffers_mapped = true;
};

// One problem found in the graph, as the command line prints it.
struct GraphDiagnostic {
  enum class Severity { error, warning, note };
  Severity severity = Severity::error;
  std::string file;  // "<command line>" for options
  int line = 0;      // 1-based; 0 = unknown
  int column = 0;
  std::string message;
};

// The graph could not be loaded or does not fit the way it is used; what() holds every
// diagnostic, one `file:line:col: error: message` per line, as `facet validate` prints them.
class GraphError : public std::runtime_error {
 public:
  GraphError(const std::string& what, std::vector<GraphDiagnostic> diagnostics)
      : std::runtime_error(what), diagnostics_(std::move(diagnostics)) {}
  const std::vector<GraphDiagnostic>& diagnostics() const noexcept { return diagnostics_; }

 private:
  std::vector<GraphDiagnostic> diagnostics_;
};

// A stage failed while a frame was processed (or while the graph was opened or closed); the
// message names the node, its stage and the frame. The same as the command line's RunError.
class ProcessError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A graph input or output: its name and the packet type it carries ("facet.DepthImage/1").
struct PortInfo {
  std::string name;
  std::string type_key;
};

struct StageTiming {
  std::string node;
  double ms = 0.0;
};

struct FrameResult {
  // By graph output name. A packet is empty when the node that makes it did not run this frame
  // (an input it requires was empty) or did not set it.
  std::map<std::string, Packet, std::less<>> outputs;
  std::vector<StageTiming> timings;   // the nodes that ran, in execution order
  std::vector<std::string> warnings;  // "node 'N', frame F: ...", as the command line prints them
  std::int64_t frame_index = 0;
  bool end_of_stream = false;  // pulled from the graph's own source, which has no more frames
};

class Pipeline {
 public:
  // Loads the plugins and the graph, checks it, then creates and opens its stages. Throws
  // GraphError with every diagnostic, or ProcessError when a stage cannot be created or opened.
  explicit Pipeline(const std::filesystem::path& graph_file, const PipelineOptions& options = {});
  // The same for a graph held in memory; `display_name` names it in diagnostics and is the base
  // of its relative paths (${graph_dir} is its directory).
  static Pipeline from_text(const std::string& yaml, const std::filesystem::path& display_name,
                            const PipelineOptions& options = {});
  ~Pipeline();  // closes the stages; a failure to close is lost: call close() to see it
  Pipeline(Pipeline&&) noexcept;
  Pipeline& operator=(Pipeline&&) noexcept;
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  const std::string& name() const;
  const std::vector<PortInfo>& inputs() const;   // empty: the graph reads its own source
  const std::vector<PortInfo>& outputs() const;  // empty only with run_sinks
  std::vector<std::string> nodes() const;        // the nodes that run, in execution order

  // Runs one frame. `inputs` holds one packet per graph input, of the declared type; throws
  // std::invalid_argument naming the input otherwise, and ProcessError when a stage fails.
  FrameResult process(const std::map<std::string, Packet, std::less<>>& inputs = {});

  // Closes every stage (sinks flush their files); throws ProcessError naming the first node that
  // failed. Calling process() afterwards throws std::logic_error.
  void close();

 private:
  class Impl;
  explicit Pipeline(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// What the plugins on the search path provide, as `facet list` and `facet inspect` show it.
struct StageSummary {
  std::string name;
  std::string plugin;   // the plugin's name
  std::string summary;  // the first line of the stage's documentation
};
std::vector<StageSummary> list_stages(const std::vector<std::filesystem::path>& plugin_paths = {});
// The text `facet inspect NAME` prints; throws std::invalid_argument for an unknown stage.
std::string inspect_stage(const std::string& name,
                          const std::vector<std::filesystem::path>& plugin_paths = {});

}  // namespace facet
