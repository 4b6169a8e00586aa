#include "report_context.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <limits>
#include <numeric>
#include <optional>

namespace facet::cli {
namespace {

std::string params_text(const NodeSpec& node) {
  std::string text;
  for (const auto& param : node.params)
    text += " " + param.name + "=" + param.text;
  return text;
}

std::optional<double> value_at(const MetricSummary& metric, std::int64_t frame) {
  for (std::size_t i = 0; i < metric.frames.size() && i < metric.values.size(); ++i) {
    if (metric.frames[i] == frame) return metric.values[i];
  }
  return std::nullopt;
}

// Variant `v`'s headline metric, when the summary has one and the variant reported it.
const MetricSummary* headline_metric(const CompareSummary& summary, std::size_t v) {
  if (!summary.headline || v >= summary.variants.size()) return nullptr;
  return summary.headline->of(summary.variants[v]);
}

}  // namespace

std::string describe_changes(const GraphSpec& written, const GraphSpec& variant) {
  std::vector<std::string> changes;
  for (const auto& node : variant.nodes) {
    const NodeSpec* before = written.find_node(node.id);
    if (before == nullptr) {
      changes.push_back("+" + node.id + ": " + node.stage + params_text(node));
    } else if (before->stage != node.stage) {
      changes.push_back(node.id + ": " + node.stage + params_text(node));
    } else {
      for (const auto& param : node.params) {
        const ParamSetting* old = before->find_param(param.name);
        if (old == nullptr || old->text != param.text) {
          changes.push_back(node.id + "." + param.name + "=" + param.text);
        }
      }
    }
  }
  for (const auto& node : written.nodes) {
    if (variant.find_node(node.id) == nullptr) changes.push_back("-" + node.id);
  }
  if (changes.empty()) return "the graph as written";
  std::string text = changes.front();
  for (std::size_t i = 1; i < changes.size(); ++i)
    text += "; " + changes[i];
  return text;
}

std::vector<std::string> frames_to_show(const CompareSummary& summary, std::size_t count,
                                        bool where_they_disagree) {
  const std::size_t frames = summary.frame_stems.size();
  std::vector<std::size_t> order(frames);
  std::iota(order.begin(), order.end(), 0);
  if (where_they_disagree && summary.variants.size() > 1) {
    std::vector<double> spread(frames, -1.0);
    for (std::size_t f = 0; f < frames; ++f) {
      double lo = std::numeric_limits<double>::infinity();
      double hi = -lo;
      for (std::size_t v = 0; v < summary.variants.size(); ++v) {
        const MetricSummary* metric = headline_metric(summary, v);
        const auto value =
            metric == nullptr ? std::nullopt : value_at(*metric, static_cast<std::int64_t>(f));
        if (!value) continue;
        lo = std::min(lo, *value);
        hi = std::max(hi, *value);
      }
      if (hi >= lo) spread[f] = hi - lo;
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return spread[a] > spread[b]; });
  }
  std::vector<std::string> stems;
  for (const std::size_t f : order) {
    if (stems.size() >= count) break;
    if (!summary.frame_stems[f].empty()) stems.push_back(summary.frame_stems[f]);
  }
  return stems;
}

std::optional<double> frame_headline(const CompareSummary& summary, std::size_t v,
                                     const std::string& stem) {
  const auto& stems = summary.frame_stems;
  const auto frame = std::find(stems.begin(), stems.end(), stem);
  const MetricSummary* metric = headline_metric(summary, v);
  if (frame == stems.end() || metric == nullptr) return std::nullopt;
  return value_at(*metric, frame - stems.begin());
}

std::string utc_now_text() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  return fmt::format("{:%Y-%m-%d %H:%M} UTC", utc);
}

}  // namespace facet::cli
