#pragma once
// The plots of a sweep: every score against one swept parameter (sweep_<node.param>.svg).

#include <cstddef>
#include <string>

#include "facet/framework/svg_plot.hpp"
#include "facet/framework/sweep_summary.hpp"

namespace facet {

// One panel per score (the summary's order), x = the values of axis `axis`, one line per
// combination of the other axes' values (a single line for a one-parameter sweep); each panel's
// best point is marked, and the headline score's panel shades its plateau along this axis.
LinePlot sweep_plot(const SweepSummary& sweep, std::size_t axis);

// "sweep_edges.threshold.svg"
std::string sweep_plot_file_name(const SweepAxis& axis);

}  // namespace facet
