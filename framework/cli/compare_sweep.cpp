#include "compare_sweep.hpp"

#include <fstream>
#include <iostream>

#include "exit_codes.hpp"
#include "facet/framework/sweep_check.hpp"
#include "facet/framework/sweep_plot.hpp"

namespace facet::cli {

PreparedSweep prepare_sweep(const std::vector<std::string>& sweep_options,
                            const std::filesystem::path& graph_file, LoadOptions options,
                            const std::string& variant, const Registry& registry) {
  PreparedSweep sweep;
  Diagnostics diagnostics;
  for (const auto& option : sweep_options) {
    auto parsed = parse_sweep_axis(option);
    if (auto* error = std::get_if<std::string>(&parsed)) {
      diagnostics.error({kCommandLineFile, 0, 0}, *error);
    } else {
      sweep.axes.push_back(std::move(std::get<SweepAxis>(parsed)));
    }
  }
  if (diagnostics.has_errors()) {
    diagnostics.print(std::cerr);
    sweep.exit_code = kUsage;
    return sweep;
  }
  // The nodes and stages as the sweep will vary them: with the variant's replacements.
  options.variant = variant;
  const GraphSpec graph = load_graph_file(graph_file, options, diagnostics);
  if (diagnostics.has_errors()) {
    diagnostics.print(std::cerr);
    sweep.exit_code = kInvalidGraph;
    return sweep;
  }
  check_sweep_axes(sweep.axes, graph, registry, options, diagnostics);
  if (diagnostics.has_errors()) {
    diagnostics.print(std::cerr);
    sweep.exit_code = kUsage;
    return sweep;
  }
  sweep.points = expand_sweep_grid(sweep.axes);
  return sweep;
}

std::optional<std::vector<SweepPlotFile>> write_sweep_plots(const std::filesystem::path& out_dir,
                                                            const SweepSummary& sweep) {
  std::vector<SweepPlotFile> plots;
  for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
    SweepPlotFile plot{sweep_plot_file_name(sweep.axes[a]), render_line_plot(sweep_plot(sweep, a))};
    const auto file = out_dir / plot.name;
    std::ofstream out(file, std::ios::binary);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" << plot.svg;
    if (!out) {
      std::cerr << "error: cannot write " << file.string() << '\n';
      return std::nullopt;
    }
    plots.push_back(std::move(plot));
  }
  return plots;
}

}  // namespace facet::cli
