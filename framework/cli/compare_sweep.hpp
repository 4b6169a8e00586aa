#pragma once
// `facet compare --sweep`: the points of a parameter sweep as variants of the comparison, and
// the plot files of its scores.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "facet/framework/graph_spec.hpp"
#include "facet/framework/registry.hpp"
#include "facet/framework/sweep_summary.hpp"

namespace facet::cli {

struct PreparedSweep {
  std::vector<SweepAxis> axes;
  std::vector<SweepPoint> points;  // one variant of the comparison each
  int exit_code = 0;               // kOk, or why the sweep cannot run (every problem is printed)
};

// Parses every --sweep option and checks it against the graph with `variant` applied (empty:
// the graph as written) and the --set options in `options`. A bad option exits kUsage; a graph
// that does not load (an unknown variant) exits kInvalidGraph.
PreparedSweep prepare_sweep(const std::vector<std::string>& sweep_options,
                            const std::filesystem::path& graph_file, LoadOptions options,
                            const std::string& variant, const Registry& registry);

struct SweepPlotFile {
  std::string name;  // "sweep_edges.threshold.svg"
  std::string svg;   // the <svg> element, as embedded in the report
};

// Writes DIR/sweep_<node.param>.svg for each swept parameter; nullopt (after saying why) when a
// file cannot be written.
std::optional<std::vector<SweepPlotFile>> write_sweep_plots(const std::filesystem::path& out_dir,
                                                            const SweepSummary& sweep);

}  // namespace facet::cli
