#include "facet/framework/sweep_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>

#include "graph_substitution.hpp"
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

// The first problem with giving `param` (described as `what`) the axis's values, each turned
// into the parameter's text by `text_of`; or an empty string.
template <typename TextOf>
std::string check_values(const SweepAxis& axis, const ParamSpec& param, const std::string& what,
                         TextOf text_of) {
  if (param.type != ParamType::integer && param.type != ParamType::real) {
    return what + " is not numeric; only int and real parameters can be swept";
  }
  if (param.type == ParamType::integer && !axis.integral) {
    return what + " takes whole numbers: start, stop and step must be written as integers";
  }
  for (const auto& value : axis.texts) {
    const std::string text = text_of(value);
    auto parsed = parse_param_value(param, text);
    if (const auto* error = std::get_if<std::string>(&parsed)) return what + ": " + *error;
    if (const auto error = check_param_value(param, std::get<ParamValue>(parsed))) {
      return what + ": " + *error;
    }
  }
  return {};
}

// The first problem with an axis of a node's parameter, or an empty string.
std::string check_node_axis(const SweepAxis& axis, const GraphSpec& graph,
                            const Registry& registry) {
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
  return check_values(axis, *param, what, [](const std::string& value) { return value; });
}

// The first problem with an axis of a graph parameter, or an empty string. The node parameters
// it sets are those written with its ${name}: each must take every value of the axis, and none
// may be swept by an axis of its own, which would silently win over this one.
std::string check_graph_param_axis(const SweepAxis& axis, const std::vector<SweepAxis>& axes,
                                   const GraphSpec& graph, const Registry& registry) {
  if (graph.params.count(axis.param) == 0) {
    std::vector<std::string> declared;
    for (const auto& [name, value] : graph.params)
      declared.push_back(name);
    return fmt::format(
        "'{}' is no node.param and no graph parameter{}", axis.param,
        detail::suggestion_suffix(axis.param, declared, "the graph's parameters are"));
  }
  const std::string reference = "${" + axis.param + "}";
  std::map<std::string, std::string> values = graph.params;
  values[detail::kGraphDirParam] = graph.graph_dir.generic_string();
  bool sets_any = false;
  for (const auto& node : graph.nodes) {
    for (const auto& setting : node.params) {
      if (setting.written.find(reference) == std::string::npos) continue;
      sets_any = true;
      const std::string target = node.id + "." + setting.name;
      const auto own_axis = std::find_if(axes.begin(), axes.end(),
                                         [&](const SweepAxis& a) { return a.key() == target; });
      if (own_axis != axes.end()) {
        return fmt::format("it sets {}, which --sweep {} sweeps too; sweep one of them", target,
                           own_axis->option);
      }
      const StageEntry* stage = registry.find(node.stage);
      const ParamSpec* param = stage == nullptr ? nullptr : stage->spec.find_param(setting.name);
      if (param == nullptr) continue;  // validation reports the unknown stage or parameter
      const std::string what =
          fmt::format("graph parameter '{}' sets parameter '{}' of node '{}' ({})", axis.param,
                      setting.name, node.id, to_string(param->type));
      const std::string problem = check_values(axis, *param, what, [&](const std::string& value) {
        values[axis.param] = value;
        Diagnostics reported_by_the_loader;
        return detail::ParamSubstitution(values)
            .expand(setting.written, setting.where, reported_by_the_loader)
            .value_or(setting.text);
      });
      if (!problem.empty()) return problem;
    }
  }
  if (!sets_any) {
    return fmt::format("graph parameter '{}' sets no node parameter (none is written with {})",
                       axis.param, reference);
  }
  return {};
}

// The command-line option that also gives the axis's parameter, or an empty string.
std::string also_given(const SweepAxis& axis, const LoadOptions& given) {
  if (axis.is_graph_param()) {
    const auto param = given.params.find(axis.param);
    return param == given.params.end() ? std::string()
                                       : "--param " + param->first + "=" + param->second;
  }
  const auto set = std::find_if(given.sets.begin(), given.sets.end(),
                                [&](const auto& s) { return s.first == axis.key(); });
  return set == given.sets.end() ? std::string() : "--set " + set->first + "=" + set->second;
}

}  // namespace

void check_sweep_axes(const std::vector<SweepAxis>& axes, const GraphSpec& graph,
                      const Registry& registry, const LoadOptions& given,
                      Diagnostics& diagnostics) {
  std::vector<std::string> keys;
  for (const auto& axis : axes) {
    const std::string option = "--sweep " + axis.option + ": ";
    if (std::find(keys.begin(), keys.end(), axis.key()) != keys.end()) {
      diagnostics.error(command_line(), fmt::format("{}'{}' is swept twice", option, axis.key()));
      continue;
    }
    keys.push_back(axis.key());
    if (const std::string other = also_given(axis, given); !other.empty()) {
      diagnostics.error(command_line(),
                        fmt::format("{}'{}' is also given by {}; a swept parameter takes the "
                                    "sweep's values only",
                                    option, axis.key(), other));
      continue;
    }
    const std::string problem = axis.is_graph_param()
                                    ? check_graph_param_axis(axis, axes, graph, registry)
                                    : check_node_axis(axis, graph, registry);
    if (!problem.empty()) diagnostics.error(command_line(), option + problem);
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
