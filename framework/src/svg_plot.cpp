#include "facet/framework/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace facet {
namespace {

// Panel geometry in pixels: the plot area is the panel less its margins.
constexpr int kPanelWidth = 300;
constexpr int kPanelHeight = 210;
constexpr int kLeft = 58;  // y tick labels
constexpr int kRight = 14;
constexpr int kTop = 26;     // panel title
constexpr int kBottom = 40;  // x tick labels and the x label
constexpr int kMargin = 10;
constexpr int kLegendRow = 18;

constexpr const char* kBestColour = "#d62728";
constexpr const char* kBandColour = "#59a14f";

struct Range {
  double lo = 0.0;
  double hi = 1.0;
};

// The data's range with a margin, so that no point sits on the frame; a flat series gets a
// small range around its value instead of a zero-height one.
Range padded(double lo, double hi) {
  const double span = hi - lo;
  if (span <= 1e-12 * std::max(1.0, std::abs(hi))) {
    const double pad = std::max(std::abs(hi) * 0.02, 1e-3);
    return {lo - pad, hi + pad};
  }
  return {lo - span * 0.06, hi + span * 0.06};
}

std::string tick_text(double value, int decimals) {
  std::string text = fmt::format("{:.{}f}", value, decimals);
  if (text.starts_with('-') && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

// Legend entries with their widths; wrapped into rows as wide as the plot.
struct LegendItem {
  std::string kind;  // "line", "best", "band"
  std::string label;
  std::size_t line = 0;
};

int item_width(const LegendItem& item) {
  return 30 + 7 * static_cast<int>(item.label.size());
}

void write_legend(std::string& svg, const std::vector<LegendItem>& items, int top, int width) {
  svg += "<g class=\"legend\">\n";
  int x = kMargin;
  int y = top;
  for (const auto& item : items) {
    if (x > kMargin && x + item_width(item) > width - kMargin) {
      x = kMargin;
      y += kLegendRow;
    }
    if (item.kind == "line") {
      svg += fmt::format(R"(<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{}" stroke-width="2"/>)",
                         x, y - 4, x + 20, y - 4, series_colour(item.line));
    } else if (item.kind == "best") {
      svg += fmt::format(R"(<circle cx="{}" cy="{}" r="5" fill="none" stroke="{}" )"
                         R"(stroke-width="2"/>)",
                         x + 10, y - 4, kBestColour);
    } else {
      svg += fmt::format(R"(<rect x="{}" y="{}" width="20" height="10" fill="{}" )"
                         R"(fill-opacity="0.18"/>)",
                         x, y - 9, kBandColour);
    }
    svg +=
        fmt::format(R"(<text x="{}" y="{}">{}</text>)", x + 26, y, xml_escape(item.label)) + "\n";
    x += item_width(item);
  }
  svg += "</g>\n";
}

int legend_rows(const std::vector<LegendItem>& items, int width) {
  int rows = items.empty() ? 0 : 1;
  int x = kMargin;
  for (const auto& item : items) {
    if (x > kMargin && x + item_width(item) > width - kMargin) {
      x = kMargin;
      ++rows;
    }
    x += item_width(item);
  }
  return rows;
}

void write_panel(std::string& svg, const LinePlot& plot, const PlotPanel& panel, int left,
                 int top) {
  const double plot_width = kPanelWidth - kLeft - kRight;
  const double plot_height = kPanelHeight - kTop - kBottom;
  svg += fmt::format(R"svg(<g class="panel" data-title="{}" transform="translate({},{})">)svg",
                     xml_escape(panel.title), left, top) +
         "\n";
  svg += fmt::format(R"(<text x="{}" y="16" font-weight="bold">{}</text>)", kLeft,
                     xml_escape(panel.title)) +
         "\n";

  double lo = INFINITY;
  double hi = -INFINITY;
  for (const auto& line : panel.lines) {
    for (const double y : line.y) {
      if (std::isnan(y)) continue;
      lo = std::min(lo, y);
      hi = std::max(hi, y);
    }
  }
  if (plot.x.empty() || !std::isfinite(lo)) {
    svg +=
        fmt::format(R"(<text x="{}" y="{}">no values</text>)", kLeft + 10, kTop + plot_height / 2) +
        "\n</g>\n";
    return;
  }
  const Range y_range = padded(lo, hi);
  const Range x_range = padded(plot.x.front(), plot.x.back());
  const auto x_of = [&](double x) {
    return kLeft + plot_width * (x - x_range.lo) / (x_range.hi - x_range.lo);
  };
  const auto y_of = [&](double y) {
    return kTop + plot_height * (1.0 - (y - y_range.lo) / (y_range.hi - y_range.lo));
  };

  if (panel.band) {
    // A band of one point is drawn a few pixels wide, so that it can be seen.
    const double x1 = x_of(panel.band->from) - 3.0;
    const double x2 = x_of(panel.band->to) + 3.0;
    svg += fmt::format(R"(<rect class="band" x="{:.1f}" y="{}" width="{:.1f}" height="{}" )"
                       R"(fill="{}" fill-opacity="0.18"><title>{}</title></rect>)",
                       x1, kTop, x2 - x1, plot_height, kBandColour, xml_escape(panel.band->note)) +
           "\n";
  }

  // Grid, ticks and their labels.
  const auto y_ticks = nice_ticks(y_range.lo, y_range.hi, 4);
  const int y_decimals = y_ticks.size() > 1 ? tick_decimals(y_ticks[1] - y_ticks[0]) : 3;
  for (const double tick : y_ticks) {
    const double y = y_of(tick);
    svg += fmt::format(R"(<line x1="{}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="#e4e4e4"/>)"
                       R"(<text x="{}" y="{:.1f}" text-anchor="end">{}</text>)",
                       kLeft, y, kLeft + plot_width, y, kLeft - 5, y + 4,
                       tick_text(tick, y_decimals)) +
           "\n";
  }
  const auto x_ticks = nice_ticks(x_range.lo, x_range.hi, 5);
  const int x_decimals = x_ticks.size() > 1 ? tick_decimals(x_ticks[1] - x_ticks[0]) : 3;
  for (const double tick : x_ticks) {
    const double x = x_of(tick);
    svg += fmt::format(R"(<line x1="{0:.1f}" y1="{1}" x2="{0:.1f}" y2="{2}" stroke="#999"/>)"
                       R"(<text x="{0:.1f}" y="{3}" text-anchor="middle">{4}</text>)",
                       x, kTop + plot_height, kTop + plot_height + 4, kTop + plot_height + 16,
                       tick_text(tick, x_decimals)) +
           "\n";
  }
  svg += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#999"/>)",
                     kLeft, kTop, plot_width, plot_height) +
         "\n";
  svg += fmt::format(R"(<text x="{:.1f}" y="{}" text-anchor="middle">{}</text>)",
                     kLeft + plot_width / 2, kPanelHeight - 6, xml_escape(plot.x_label)) +
         "\n";

  for (std::size_t l = 0; l < panel.lines.size(); ++l) {
    const PlotLine& line = panel.lines[l];
    std::string points;
    std::string dots;
    for (std::size_t i = 0; i < line.y.size() && i < plot.x.size(); ++i) {
      if (std::isnan(line.y[i])) continue;
      const double x = x_of(plot.x[i]);
      const double y = y_of(line.y[i]);
      if (!points.empty()) points += ' ';
      points += fmt::format("{:.1f},{:.1f}", x, y);
      dots += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="2"/>)", x, y);
    }
    svg += fmt::format(R"(<polyline class="line" fill="none" stroke="{}" stroke-width="1.5" )"
                       R"(points="{}"><title>{}</title></polyline>)",
                       series_colour(l), points, xml_escape(line.label)) +
           "\n";
    svg += fmt::format(R"(<g fill="{}">{}</g>)", series_colour(l), dots) + "\n";
  }
  if (panel.best && panel.best->line < panel.lines.size() && panel.best->x < plot.x.size()) {
    const double y = panel.lines[panel.best->line].y[panel.best->x];
    svg += fmt::format(R"(<circle class="best" cx="{:.1f}" cy="{:.1f}" r="5" fill="none" )"
                       R"(stroke="{}" stroke-width="2"><title>{}</title></circle>)",
                       x_of(plot.x[panel.best->x]), y_of(y), kBestColour,
                       xml_escape(panel.best->note)) +
           "\n";
  }
  svg += "</g>\n";
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo) || target < 1) return {lo};
  const double raw = (hi - lo) / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normal = raw / magnitude;
  const double step = (normal < 1.5   ? 1.0
                       : normal < 3.5 ? 2.0
                       : normal < 7.5 ? 5.0
                                      : 10.0) *
                      magnitude;
  const auto first = static_cast<long long>(std::ceil(lo / step - 1e-9));
  const auto last = static_cast<long long>(std::floor(hi / step + 1e-9));
  std::vector<double> ticks;
  for (long long k = first; k <= last; ++k)
    ticks.push_back(static_cast<double>(k) * step);
  return ticks;
}

int tick_decimals(double step) {
  if (!(step > 0.0)) return 0;
  return std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
}

std::string render_line_plot(const LinePlot& plot) {
  const int columns =
      std::max(1, std::min<int>(plot.columns, static_cast<int>(plot.panels.size())));
  const int rows = (static_cast<int>(plot.panels.size()) + columns - 1) / columns;
  const int width = 2 * kMargin + columns * kPanelWidth;

  std::vector<LegendItem> legend;
  if (!plot.panels.empty()) {
    for (std::size_t l = 0; l < plot.panels.front().lines.size(); ++l)
      legend.push_back({"line", plot.panels.front().lines[l].label, l});
  }
  const bool any_best = std::any_of(plot.panels.begin(), plot.panels.end(),
                                    [](const PlotPanel& p) { return p.best.has_value(); });
  const bool any_band = std::any_of(plot.panels.begin(), plot.panels.end(),
                                    [](const PlotPanel& p) { return p.band.has_value(); });
  if (any_best) legend.push_back({"best", "best point of each score", 0});
  if (any_band) legend.push_back({"band", plot.band_legend, 0});
  const int legend_top = 44;
  const int panels_top = legend_top + legend_rows(legend, width) * kLegendRow;
  const int height = panels_top + rows * kPanelHeight + kMargin;

  std::string svg = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" class="sweep" width="{0}" height="{1}" )"
      R"(viewBox="0 0 {0} {1}" font-family="sans-serif" font-size="11" role="img" )"
      R"(aria-label="{2}">)",
      width, height, xml_escape(plot.title));
  svg += "\n<title>" + xml_escape(plot.title) + "</title>\n";
  svg += fmt::format(R"(<rect width="{}" height="{}" fill="#ffffff"/>)", width, height) + "\n";
  svg += fmt::format(R"(<text x="{}" y="22" font-size="15" font-weight="bold">{}</text>)", kMargin,
                     xml_escape(plot.title)) +
         "\n";
  write_legend(svg, legend, legend_top, width);
  for (std::size_t p = 0; p < plot.panels.size(); ++p) {
    const int column = static_cast<int>(p) % columns;
    const int row = static_cast<int>(p) / columns;
    write_panel(svg, plot, plot.panels[p], kMargin + column * kPanelWidth,
                panels_top + row * kPanelHeight);
  }
  svg += "</svg>\n";
  return svg;
}

const char* series_colour(std::size_t index) {
  static constexpr const char* kColours[] = {"#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2",
                                             "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
  return kColours[index % std::size(kColours)];
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace facet
