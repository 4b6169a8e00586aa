#include "facet/framework/sweep_spec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "yaml_checks.hpp"

namespace facet {
namespace {

// Digits after the point that `text` needs, exponent included: "0.01" 2, "1e-3" 3, "2.5e1" 0.
int decimals_of(std::string_view text) {
  const auto e = text.find_first_of("eE");
  const std::string_view mantissa = text.substr(0, e);
  int exponent = 0;
  if (e != std::string_view::npos) {
    const std::string_view digits = text.substr(e + 1);
    std::from_chars(digits.data() + (digits.starts_with('+') ? 1 : 0),
                    digits.data() + digits.size(), exponent);
  }
  const auto dot = mantissa.find('.');
  const int fraction =
      dot == std::string_view::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  // Beyond 12 digits a sweep step is below what the report can show apart.
  return std::clamp(fraction - exponent, 0, 12);
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::string format_value(double value, int decimals) {
  std::string text = fmt::format("{:.{}f}", value, decimals);
  // -0.00 (start + i * step landing a hair below zero) is 0.00.
  if (text.starts_with('-') && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t from = 0;
  for (std::size_t at = text.find(separator); at != std::string_view::npos;
       at = text.find(separator, from)) {
    parts.push_back(text.substr(from, at - from));
    from = at + 1;
  }
  parts.push_back(text.substr(from));
  return parts;
}

constexpr std::string_view kExpected =
    "expected node.param=start:stop:step or param=start:stop:step";

}  // namespace

std::variant<SweepAxis, std::string> parse_sweep_axis(std::string_view option) {
  const std::string prefix = "--sweep " + std::string(option) + ": ";
  const auto fail = [&](const std::string& why) { return prefix + why; };
  const auto eq = option.find('=');
  if (eq == std::string_view::npos) return fail(std::string(kExpected));
  const std::string_view target = option.substr(0, eq);
  const auto dot = target.find('.');
  // No dot: a graph parameter, checked against the graph's `params:` later.
  const std::string_view node = dot == std::string_view::npos ? "" : target.substr(0, dot);
  const std::string_view param = dot == std::string_view::npos ? target : target.substr(dot + 1);
  if ((dot != std::string_view::npos && !detail::is_identifier(node)) ||
      !detail::is_identifier(param)) {
    return fail(fmt::format("'{}' is neither node.param nor a graph parameter's name", target));
  }
  const auto range = split(option.substr(eq + 1), ':');
  if (range.size() != 3) return fail("expected start:stop:step after the '='");

  SweepAxis axis;
  axis.option = std::string(option);
  axis.node = std::string(node);
  axis.param = std::string(param);
  double* const bounds[] = {&axis.start, &axis.stop, &axis.step};
  const char* const names[] = {"start", "stop", "step"};
  axis.integral = true;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto number = parse_number(range[i]);
    if (!number)
      return fail(std::string(names[i]) + " '" + std::string(range[i]) + "' is not a number");
    *bounds[i] = *number;
    const int decimals = decimals_of(range[i]);
    axis.decimals = std::max(axis.decimals, decimals);
    axis.integral = axis.integral && decimals == 0 && std::floor(*number) == *number;
  }
  if (axis.step <= 0.0) return fail(fmt::format("step must be positive, got {}", range[2]));
  if (axis.start > axis.stop) {
    return fail(fmt::format("start {} is above stop {}; give start <= stop", range[0], range[1]));
  }
  const double steps = (axis.stop - axis.start) / axis.step;
  // Tolerance for a stop that is meant to be on the grid but is off by rounding (0.9 - 0.8).
  if (steps + 1.0 > static_cast<double>(kMaxSweepPoints) + 1e-6) {
    return fail(fmt::format("{:.4g} points; at most {} (a larger step or a narrower range)",
                            std::floor(steps + 1e-6) + 1.0, kMaxSweepPoints));
  }
  const auto count = static_cast<std::size_t>(std::floor(steps + 1e-6)) + 1;
  for (std::size_t i = 0; i < count; ++i) {
    const double value = axis.start + static_cast<double>(i) * axis.step;
    axis.texts.push_back(format_value(value, axis.decimals));
    axis.values.push_back(*parse_number(axis.texts.back()));
  }
  return axis;
}

std::optional<std::size_t> sweep_grid_size(const std::vector<SweepAxis>& axes) {
  if (axes.empty()) return 0;
  std::size_t size = 1;
  for (const auto& axis : axes) {
    // Each factor is at most kMaxSweepPoints, so the product cannot overflow before it is caught.
    size *= axis.values.size();
    if (size > kMaxSweepPoints) return std::nullopt;
  }
  return size;
}

std::vector<SweepPoint> expand_sweep_grid(const std::vector<SweepAxis>& axes) {
  std::vector<SweepPoint> points;
  if (axes.empty() || !sweep_grid_size(axes)) return points;
  std::vector<std::size_t> index(axes.size(), 0);
  while (true) {
    SweepPoint point;
    point.index = index;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const std::string& text = axes[a].texts[index[a]];
      if (a > 0) point.name += ',';
      point.name += axes[a].key() + "=" + text;
      auto& assignments = axes[a].is_graph_param() ? point.params : point.sets;
      assignments.emplace_back(axes[a].key(), text);
    }
    points.push_back(std::move(point));
    // Odometer: the last axis turns fastest.
    std::size_t a = axes.size();
    while (a > 0) {
      --a;
      if (++index[a] < axes[a].values.size()) break;
      index[a] = 0;
      if (a == 0) return points;
    }
  }
}

}  // namespace facet
