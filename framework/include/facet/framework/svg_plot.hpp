#pragma once
// Line plots written as SVG text, without a plotting library: one or more panels that share an
// x axis, each with its own y axis (ticks at round numbers, the range fitted to the data rather
// than started at 0, so that close scores stay apart), a marked best point, an optional shaded
// x range, and one legend for all panels. The output loads nothing and runs no script.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace facet {

struct PlotLine {
  std::string label;
  std::vector<double> y;  // one per x value; NaN = no value there (the line skips it)
};

struct PlotMark {
  std::size_t line = 0;  // index into PlotPanel::lines
  std::size_t x = 0;     // index into LinePlot::x
  std::string note;      // tooltip: "best 0.971 at edges.threshold=0.85"
};

struct PlotBand {
  double from = 0.0;  // x range, in data units
  double to = 0.0;
  std::string note;
};

struct PlotPanel {
  std::string title;  // "score.f"
  std::vector<PlotLine> lines;
  std::optional<PlotMark> best;
  std::optional<PlotBand> band;
};

struct LinePlot {
  std::string title;
  std::string x_label;
  std::vector<double> x;  // ascending
  std::vector<PlotPanel> panels;
  std::string band_legend;  // legend text of the shaded range, when a panel has one
  int columns = 3;          // panels per row
};

// The plot as one <svg> element (no XML declaration: it can be written to a file after one or
// embedded in HTML as it is). Each line is one <polyline class="line"> inside its panel's
// <g class="panel" data-title="...">, with one point per x that has a value.
std::string render_line_plot(const LinePlot& plot);

// Round tick values covering [lo, hi]: about `target` of them, steps of 1, 2 or 5 times a power
// of ten, each computed as a multiple of the step (no accumulated rounding).
std::vector<double> nice_ticks(double lo, double hi, int target = 5);

// Digits after the point that ticks `step` apart need: 0.02 -> 2, 5 -> 0.
int tick_decimals(double step);

// The colour of series `index` (ten fixed colours, then they repeat), the same in every plot of
// the compare report and in the sweep plots, so a variant keeps its colour throughout.
const char* series_colour(std::size_t index);

// Text made safe for XML and HTML element content and attribute values (<, >, &, ", ').
std::string xml_escape(const std::string& text);

}  // namespace facet
