// Checking a GraphSpec against the registered stages: stages, parameters, ports and their types,
// required inputs, cycles; then ordering the nodes for execution.

#include <algorithm>
#include <filesystem>
#include <map>

#include "facet/framework/validated_graph.hpp"
#include "graph_order.hpp"
#include "yaml_checks.hpp"

namespace facet {
namespace {

using detail::in_quotes;
using detail::suggestion_suffix;

template <class Item>
std::vector<std::string> names_of(const std::vector<Item>& items) {
  std::vector<std::string> names;
  for (const auto& item : items)
    names.push_back(item.name);
  return names;
}

// One node while it is being checked; `inputs` hold file indices until the order is known.
struct CheckedNode {
  const NodeSpec* spec = nullptr;
  const StageEntry* stage = nullptr;
  Params params;
  std::vector<std::optional<Connection>> inputs;
};

class GraphValidator {
 public:
  GraphValidator(const GraphSpec& graph, const Registry& registry, Diagnostics& diagnostics)
      : graph_(graph), registry_(registry), diagnostics_(diagnostics) {
    for (const auto& node : graph_.nodes)
      node_ids_.push_back(node.id);
  }

  ValidatedGraph run() {
    checked_.resize(graph_.nodes.size());
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i) {
      checked_[i].spec = &graph_.nodes[i];
      check_stage(checked_[i]);
    }
    for (auto& node : checked_) {
      check_params(node);
      check_inputs(node);
    }
    inputs_ = check_graph_ports(graph_.inputs, "input");
    outputs_ = check_graph_ports(graph_.outputs, "output");
    for (const auto& cycle : detail::find_cycles(checked_.size(), dependencies_)) {
      std::vector<std::string> names;
      for (const std::size_t v : cycle.path)
        names.push_back(graph_.nodes[v].id);
      diagnostics_.error(cycle.where, "cycle: " + detail::join(names, " -> "));
    }
    check_sink_folders();
    // Only for a graph that is otherwise right: after errors, it would be noise.
    if (!diagnostics_.has_errors()) warn_unread_nodes();
    return ordered_result();
  }

 private:
  // Two sinks writing one folder overwrite each other's files (both name them after the frame).
  void check_sink_folders() {
    std::map<std::filesystem::path, const CheckedNode*> writer_of;
    for (const auto& node : checked_) {
      if (node.stage == nullptr || !node.stage->spec.outputs().empty() ||
          !node.params.contains("dir")) {
        continue;
      }
      const std::string& dir = node.params.get_string("dir");
      if (dir.empty()) continue;
      auto folder = std::filesystem::path(dir).lexically_normal();
      if (!folder.has_filename()) folder = folder.parent_path();  // "out/" is "out"

      const auto [first, inserted] = writer_of.emplace(folder, &node);
      if (inserted) continue;
      diagnostics_.error(node.spec->where,
                         "node " + in_quotes(node.spec->id) + " writes to folder " +
                             in_quotes(dir) + ", as node " + in_quotes(first->second->spec->id) +
                             " does: their files would overwrite each other; give each sink "
                             "its own dir");
    }
  }

  // A node whose outputs nothing reads does work for nobody: usually a sink was forgotten or a
  // connection names the wrong node. Sinks have no outputs; graph outputs count as readers.
  void warn_unread_nodes() {
    std::vector<bool> read(checked_.size(), false);
    for (const auto& node : checked_) {
      for (const auto& input : node.inputs) {
        if (input && input->from_node < read.size()) read[input->from_node] = true;
      }
    }
    for (const auto& port : outputs_) {
      if (port.port.from_node < read.size()) read[port.port.from_node] = true;
    }
    for (std::size_t i = 0; i < checked_.size(); ++i) {
      const CheckedNode& node = checked_[i];
      if (read[i] || node.stage == nullptr || node.stage->spec.outputs().empty()) continue;
      diagnostics_.warning(node.spec->where, "node " + in_quotes(node.spec->id) + " (" +
                                                 node.spec->stage +
                                                 "): nothing reads its outputs; connect them, "
                                                 "or remove the node");
    }
  }

  void check_stage(CheckedNode& node) {
    const NodeSpec& spec = *node.spec;
    if (spec.stage.empty()) return;  // reported by the loader
    node.stage = registry_.find(spec.stage);
    if (node.stage != nullptr) {
      node.params = node.stage->spec.default_params();
      node.inputs.resize(node.stage->spec.inputs().size());
      return;
    }
    diagnostics_.error(spec.stage_where,
                       "unknown stage " + in_quotes(spec.stage) + " for node " +
                           in_quotes(spec.id) +
                           suggestion_suffix(spec.stage, registry_.stage_names(), ""));
    for (const auto& failure : registry_.failures()) {
      diagnostics_.note({}, "it may be provided by a plugin that failed to load: " +
                                failure.file.string() + ": " + failure.reason);
    }
  }

  // "; did you mean 'metric'?" for a mistyped string choice ('metrc'), else nothing.
  static std::string choice_suggestion(const ParamSpec& param, const ParamValue& value) {
    const auto* text = std::get_if<std::string>(&value);
    if (text == nullptr) return {};
    std::vector<std::string> choices;
    for (const ParamValue& choice : param.options.choices) {
      if (const auto* name = std::get_if<std::string>(&choice)) choices.push_back(*name);
    }
    const std::string guess = did_you_mean(*text, choices);
    return guess.empty() ? std::string() : "; did you mean '" + guess + "'?";
  }

  void check_params(CheckedNode& node) {
    if (node.stage == nullptr) return;
    const NodeSpec& spec = *node.spec;
    const StageSpec& stage = node.stage->spec;
    for (const auto& setting : spec.params) {
      const ParamSpec* param = stage.find_param(setting.name);
      if (param == nullptr) {
        diagnostics_.error(
            setting.where,
            "stage " + in_quotes(stage.name()) + " has no parameter " + in_quotes(setting.name) +
                (stage.params().empty() ? std::string("; it takes none")
                                        : suggestion_suffix(setting.name, names_of(stage.params()),
                                                            "its parameters are")));
        continue;
      }
      if (!setting.resolved) continue;  // the loader reported it
      // A --set option has no line to point at: repeat the option instead.
      const std::string option =
          setting.where.file == kCommandLineFile
              ? "--set " + spec.id + "." + setting.name + "=" + setting.text + ": "
              : std::string();
      const std::string what = option + "parameter " + in_quotes(setting.name) + " of node " +
                               in_quotes(spec.id) + " (" + std::string(to_string(param->type)) +
                               "): ";
      auto parsed = parse_param_value(*param, setting.text);
      if (const auto* error = std::get_if<std::string>(&parsed)) {
        diagnostics_.error(setting.where, what + *error);
        continue;
      }
      const ParamValue& value = std::get<ParamValue>(parsed);
      if (const auto error = check_param_value(*param, value)) {
        diagnostics_.error(setting.where, what + *error + choice_suggestion(*param, value));
        continue;
      }
      node.params.set(setting.name, value);
    }
    for (const auto& param : stage.params()) {
      if (!param.options.required) continue;
      const bool set = std::any_of(spec.params.begin(), spec.params.end(),
                                   [&](const ParamSetting& s) { return s.name == param.name; });
      if (!set) {
        diagnostics_.error(spec.where, "node " + in_quotes(spec.id) + ": required parameter " +
                                           in_quotes(param.name) + " (" +
                                           std::string(to_string(param.type)) + ") of stage " +
                                           in_quotes(stage.name()) + " is not set");
      }
    }
  }

  void check_inputs(CheckedNode& node) {
    const NodeSpec& spec = *node.spec;
    if (node.stage != nullptr && node.stage->spec.is_source() && spec.inputs_where) {
      diagnostics_.error(*spec.inputs_where, "node " + in_quotes(spec.id) + ": stage " +
                                                 in_quotes(spec.stage) +
                                                 " is a source and takes no inputs");
      note_replacement(spec);
      return;
    }
    std::vector<bool> connected(node.inputs.size(), false);
    for (const auto& binding : spec.inputs)
      check_binding(node, binding, connected);
    if (node.stage == nullptr) return;
    const auto& ports = node.stage->spec.inputs();
    for (std::size_t i = 0; i < ports.size(); ++i) {
      if (!ports[i].required || connected[i]) continue;
      diagnostics_.error(spec.where, "node " + in_quotes(spec.id) + ": required input " +
                                         in_quotes(ports[i].name) + " (" + ports[i].type_key +
                                         ") of stage " + in_quotes(spec.stage) +
                                         " is not connected");
      note_replacement(spec);
    }
  }

  void check_binding(CheckedNode& node, const InputBinding& binding, std::vector<bool>& connected) {
    const NodeSpec& spec = *node.spec;
    const PortSpec* input = nullptr;
    std::size_t input_index = 0;
    if (node.stage != nullptr) {
      const StageSpec& stage = node.stage->spec;
      input = stage.find_input(binding.port);
      if (input == nullptr) {
        diagnostics_.error(
            binding.where,
            "stage " + in_quotes(stage.name()) + " of node " + in_quotes(spec.id) +
                " has no input " + in_quotes(binding.port) +
                suggestion_suffix(binding.port, names_of(stage.inputs()), "its inputs are"));
        note_replacement(spec);
      } else {
        input_index = static_cast<std::size_t>(input - stage.inputs().data());
        // Counted as connected even if the reference is broken: that error is reported once.
        connected[input_index] = true;
      }
    }
    if (binding.from_node.empty()) return;  // malformed reference, reported by the loader

    const auto producer_it = std::find(node_ids_.begin(), node_ids_.end(), binding.from_node);
    if (producer_it == node_ids_.end() &&
        report_left_out(binding.from_node, binding.where,
                        "input " + in_quotes(binding.port) + " of node " + in_quotes(spec.id))) {
      return;
    }
    if (producer_it == node_ids_.end()) {
      diagnostics_.error(binding.where, "unknown node " + in_quotes(binding.from_node) +
                                            " in input " + in_quotes(binding.port) + " of node " +
                                            in_quotes(spec.id) +
                                            suggestion_suffix(binding.from_node, node_ids_, ""));
      return;
    }
    const auto producer_index = static_cast<std::size_t>(producer_it - node_ids_.begin());
    const std::size_t consumer_index = static_cast<std::size_t>(&node - checked_.data());
    dependencies_.push_back({producer_index, consumer_index, binding.where});

    const CheckedNode& producer = checked_[producer_index];
    if (producer.stage == nullptr) return;
    const StageSpec& producer_stage = producer.stage->spec;
    const PortSpec* output = producer_stage.find_output(binding.from_port);
    if (output == nullptr) {
      diagnostics_.error(
          binding.where,
          "stage " + in_quotes(producer_stage.name()) + " of node " + in_quotes(binding.from_node) +
              " has no output " + in_quotes(binding.from_port) +
              suggestion_suffix(binding.from_port, names_of(producer_stage.outputs()),
                                "its outputs are"));
      note_replacement(*producer.spec);
      return;
    }
    if (input == nullptr) return;
    if (output->type_key != input->type_key) {
      diagnostics_.error(binding.where, "type mismatch: input " +
                                            in_quotes(spec.id + "." + input->name) + " takes " +
                                            input->type_key + " but output " +
                                            in_quotes(binding.from_node + "." + output->name) +
                                            " gives " + output->type_key);
      note_replacement(spec);
      note_replacement(*producer.spec);
      return;
    }
    const auto output_index = static_cast<std::size_t>(output - producer_stage.outputs().data());
    node.inputs[input_index] = Connection{producer_index, output_index};
  }

  // Graph inputs and outputs name an output port of a node, like a node's `in:` does.
  std::vector<ValidatedGraphPort> check_graph_ports(const std::vector<GraphPort>& ports,
                                                    const std::string& what) {
    std::vector<ValidatedGraphPort> out;
    for (const auto& port : ports) {
      const auto node_it = std::find(node_ids_.begin(), node_ids_.end(), port.node);
      if (node_it == node_ids_.end() &&
          report_left_out(port.node, port.where, "graph " + what + " " + in_quotes(port.name))) {
        continue;
      }
      if (node_it == node_ids_.end()) {
        diagnostics_.error(port.where, "unknown node " + in_quotes(port.node) + " in graph " +
                                           what + " " + in_quotes(port.name) +
                                           suggestion_suffix(port.node, node_ids_, ""));
        continue;
      }
      const auto node_index = static_cast<std::size_t>(node_it - node_ids_.begin());
      const CheckedNode& node = checked_[node_index];
      if (node.stage == nullptr) continue;  // reported with the node
      const StageSpec& stage = node.stage->spec;
      const PortSpec* output = stage.find_output(port.port);
      if (output == nullptr) {
        diagnostics_.error(
            port.where,
            "stage " + in_quotes(stage.name()) + " of node " + in_quotes(port.node) +
                " has no output " + in_quotes(port.port) + " (graph " + what + " " +
                in_quotes(port.name) + ")" +
                suggestion_suffix(port.port, names_of(stage.outputs()), "its outputs are"));
        note_replacement(*node.spec);
        continue;
      }
      const auto output_index = static_cast<std::size_t>(output - stage.outputs().data());
      out.push_back(
          {port.name, Connection{node_index, output_index}, output->type_key, port.where});
    }
    return out;
  }

  // A reference to a node that `when:` left out. True when it was one (and is reported).
  bool report_left_out(const std::string& node, const SourceLocation& where,
                       const std::string& what) {
    const auto it = std::find_if(graph_.left_out.begin(), graph_.left_out.end(),
                                 [&](const LeftOutNode& left) { return left.id == node; });
    if (it == graph_.left_out.end()) return false;
    diagnostics_.error(where,
                       "node " + in_quotes(node) + " in " + what + " is left out: " + it->reason);
    diagnostics_.note(it->where, it->note);
    return true;
  }

  // After a port error on a node whose stage a variant replaced: the ports differ because of it.
  void note_replacement(const NodeSpec& spec) {
    if (spec.replaced_by_variant.empty()) return;
    diagnostics_.note(spec.stage_where, "variant " + in_quotes(spec.replaced_by_variant) +
                                            " replaced stage " + in_quotes(spec.replaced_stage) +
                                            " of node " + in_quotes(spec.id) + " with " +
                                            in_quotes(spec.stage) +
                                            "; the replacement must provide the ports the graph "
                                            "uses, with the same types");
  }

  ValidatedGraph ordered_result() {
    const auto order = detail::topological_order(checked_.size(), dependencies_);
    std::vector<std::size_t> position(order.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      position[order[i]] = i;

    ValidatedGraph result;
    result.name = graph_.name;
    result.file = graph_.file;
    for (const std::size_t index : order) {
      CheckedNode& node = checked_[index];
      ValidatedNode out;
      out.id = node.spec->id;
      out.stage = node.stage;
      out.params = std::move(node.params);
      out.where = node.spec->where;
      for (auto& input : node.inputs) {
        if (input) input->from_node = position[input->from_node];
      }
      out.inputs = std::move(node.inputs);
      result.nodes.push_back(std::move(out));
    }
    for (auto* ports : {&inputs_, &outputs_}) {
      for (auto& port : *ports)
        port.port.from_node = position[port.port.from_node];
    }
    result.inputs = std::move(inputs_);
    result.outputs = std::move(outputs_);
    return result;
  }

  const GraphSpec& graph_;
  const Registry& registry_;
  Diagnostics& diagnostics_;
  std::vector<std::string> node_ids_;
  std::vector<CheckedNode> checked_;
  std::vector<detail::Dependency> dependencies_;
  std::vector<ValidatedGraphPort> inputs_;
  std::vector<ValidatedGraphPort> outputs_;
};

}  // namespace

const ValidatedNode* ValidatedGraph::find(const std::string& id) const {
  const auto it =
      std::find_if(nodes.begin(), nodes.end(), [&](const ValidatedNode& n) { return n.id == id; });
  return it == nodes.end() ? nullptr : &*it;
}

ValidatedGraph validate_graph(const GraphSpec& graph, const Registry& registry,
                              Diagnostics& diagnostics) {
  return GraphValidator(graph, registry, diagnostics).run();
}

}  // namespace facet
