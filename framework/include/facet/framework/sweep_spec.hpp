#pragma once
// `facet compare --sweep node.param=start:stop:step` (a node's parameter) or
// `--sweep param=start:stop:step` (a graph parameter, which may feed several nodes): one swept
// parameter (an axis) with its values, and the grid of points that several axes span together.
// Each point becomes one variant of the comparison.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace facet {

// More points than this make a run too long and a report too large to read.
inline constexpr std::size_t kMaxSweepPoints = 200;

struct SweepAxis {
  std::string option;  // as given: "edges.threshold=0.80:0.90:0.01"
  std::string node;    // "edges"; empty for a graph parameter
  std::string param;   // "threshold", or the graph parameter's name: "edge_threshold"
  double start = 0.0;
  double stop = 0.0;
  double step = 0.0;
  // Digits after the point in every value's text: as many as the most precise of start, stop
  // and step is written with, so that "0.80:0.90:0.01" gives 0.80, 0.81, ... and not 0.8100000001.
  int decimals = 0;
  bool integral = false;  // start, stop and step are all written as integers
  // start + i * step (never a running sum, which would accumulate rounding), rounded to
  // `decimals`; `texts` are the same values as passed to the stage and shown in names.
  std::vector<double> values;
  std::vector<std::string> texts;

  bool is_graph_param() const { return node.empty(); }
  // "edges.threshold", or "edge_threshold" for a graph parameter.
  std::string key() const { return is_graph_param() ? param : node + "." + param; }
};

// Parses one --sweep option; the error names the problem and repeats the option.
std::variant<SweepAxis, std::string> parse_sweep_axis(std::string_view option);

// The number of points of the grid, or nullopt when it exceeds kMaxSweepPoints (or overflows).
std::optional<std::size_t> sweep_grid_size(const std::vector<SweepAxis>& axes);

struct SweepPoint {
  std::vector<std::size_t> index;  // per axis, into its values
  std::string name;                // "edges.threshold=0.85,planes.distance_m=0.012"
  std::vector<std::pair<std::string, std::string>> sets;    // node.param -> value text
  std::vector<std::pair<std::string, std::string>> params;  // graph parameter -> value text
};

// Every combination of the axes' values, the first axis varying slowest (as nested loops in the
// order the options were given). Empty for no axes.
std::vector<SweepPoint> expand_sweep_grid(const std::vector<SweepAxis>& axes);

}  // namespace facet
