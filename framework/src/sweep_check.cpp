#include "facet/framework/sweep_check.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "yaml_checks.hpp"

namespace facet {
namespace {

SourceLocation command_line() {
  return {kCommandLineFile, 0, 0};
}

std::vector<std::string> node_ids(const GraphSpec& graph) {
  std::vector<std::string> ids;
  for (const auto& node : graph.nodes)
    ids.push_back(node.id);
  return ids;
}

std::vector<std::string> param_names(const StageSpec& stage) {
  std::vector<std::string> names;
  for (const auto& param : stage.params())
    names.push_back(param.name);
  return names;
}

// The first problem with one axis, or an empty string.
std::string check_axis(const SweepAxis& axis, const GraphSpec& graph, const Registry& registry) {
  const NodeSpec* node = graph.find_node(axis.node);
  if (node == nullptr) {
    return fmt::format("unknown node '{}'{}", axis.node,
                       detail::suggestion_suffix(axis.node, node_ids(graph), ""));
  }
  const StageEntry* stage = registry.find(node->stage);
  if (stage == nullptr) return {};  // validation reports the unknown stage, once
  const ParamSpec* param = stage->spec.find_param(axis.param);
  if (param == nullptr) {
    return fmt::format(
        "stage '{}' of node '{}' has no parameter '{}'{}", stage->spec.name(), axis.node,
        axis.param,
        detail::suggestion_suffix(axis.param, param_names(stage->spec), "its parameters are"));
  }
  const std::string what = fmt::format("parameter '{}' of node '{}' ({})", axis.param, axis.node,
                                       to_string(param->type));
  if (param->type != ParamType::integer && param->type != ParamType::real) {
    return what + " is not numeric; only int and real parameters can be swept";
  }
  if (param->type == ParamType::integer && !axis.integral) {
    return what + " takes whole numbers: start, stop and step must be written as integers";
  }
  for (const auto& text : axis.texts) {
    auto parsed = parse_param_value(*param, text);
    if (const auto* error = std::get_if<std::string>(&parsed)) return what + ": " + *error;
    if (const auto error = check_param_value(*param, std::get<ParamValue>(parsed))) {
      return what + ": " + *error;
    }
  }
  return {};
}

}  // namespace

void check_sweep_axes(const std::vector<SweepAxis>& axes, const GraphSpec& graph,
                      const Registry& registry,
                      const std::vector<std::pair<std::string, std::string>>& sets,
                      Diagnostics& diagnostics) {
  std::vector<std::string> keys;
  for (const auto& axis : axes) {
    const std::string option = "--sweep " + axis.option + ": ";
    if (std::find(keys.begin(), keys.end(), axis.key()) != keys.end()) {
      diagnostics.error(command_line(), fmt::format("{}'{}' is swept twice", option, axis.key()));
      continue;
    }
    keys.push_back(axis.key());
    const auto set = std::find_if(sets.begin(), sets.end(),
                                  [&](const auto& s) { return s.first == axis.key(); });
    if (set != sets.end()) {
      diagnostics.error(command_line(),
                        fmt::format("{}'{}' is also given by --set {}={}; a swept parameter takes "
                                    "the sweep's values only",
                                    option, axis.key(), set->first, set->second));
      continue;
    }
    if (const std::string problem = check_axis(axis, graph, registry); !problem.empty()) {
      diagnostics.error(command_line(), option + problem);
    }
  }
  if (axes.size() > 1 && !sweep_grid_size(axes)) {
    std::string product;
    double size = 1.0;
    for (const auto& axis : axes) {
      if (!product.empty()) product += " x ";
      product += std::to_string(axis.values.size());
      size *= static_cast<double>(axis.values.size());
    }
    diagnostics.error(command_line(),
                      fmt::format("--sweep: the grid has {} = {:.0f} points; at most {} (larger "
                                  "steps, narrower ranges or fewer swept parameters)",
                                  product, size, kMaxSweepPoints));
  }
}

}  // namespace facet
