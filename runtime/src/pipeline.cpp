// facet::Pipeline: the graph loaded and checked as `facet run` does it, then run one frame per
// call, nodes in topological order (as SequentialExecutor does), with the host's packets standing
// in for the outputs of the nodes that produce the graph inputs.

#include "facet/pipeline.hpp"

#include <algorithm>
#include <boost/dll/runtime_symbol_info.hpp>
#include <cstdlib>
#include <sstream>

#include "facet/context.hpp"
#include "facet/framework/allocator_tuning.hpp"
#include "facet/framework/diagnostics.hpp"
#include "facet/framework/executor.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/plugin_loader.hpp"
#include "facet/framework/registry.hpp"
#include "facet/framework/stage_doc.hpp"
#include "facet/framework/validated_graph.hpp"
#include "node_runtime.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

std::string environment_plugin_path() {
  const char* value = std::getenv("FACET_PLUGIN_PATH");  // NOLINT(concurrency-mt-unsafe)
  return value == nullptr ? std::string() : std::string(value);
}

// The bundled plugins relative to this library: lib/libfacet_runtime.so beside lib/facet/plugins,
// in the build tree and in an install tree alike. A host program is not the facet executable, so
// the executable's own directory says nothing about where the plugins are.
std::vector<fs::path> runtime_plugin_dirs(std::vector<fs::path> dirs) {
  boost::dll::fs::error_code error;
  const auto library = boost::dll::this_line_location(error);
  if (!error && !library.empty()) {
    dirs.push_back(fs::path(library.parent_path().native()) / "facet" / "plugins");
  }
  return dirs;
}

Registry load_registry(const std::vector<fs::path>& plugin_paths,
                       const std::vector<fs::path>& graph_plugin_paths) {
  Registry registry;
  load_plugins(plugin_search_dirs(runtime_plugin_dirs(plugin_paths), environment_plugin_path(),
                                  graph_plugin_paths),
               registry);
  return registry;
}

GraphDiagnostic::Severity severity_of(Severity severity) {
  switch (severity) {
    case Severity::error:
      return GraphDiagnostic::Severity::error;
    case Severity::warning:
      return GraphDiagnostic::Severity::warning;
    case Severity::note:
      break;
  }
  return GraphDiagnostic::Severity::note;
}

[[noreturn]] void throw_graph_error(const Diagnostics& diagnostics) {
  std::vector<GraphDiagnostic> copy;
  for (const auto& item : diagnostics.all()) {
    copy.push_back({severity_of(item.severity), item.where.file, item.where.line, item.where.column,
                    item.message});
  }
  throw GraphError(diagnostics.str(), std::move(copy));
}

std::string in_quotes(const std::string& text) {
  return "'" + text + "'";
}

}  // namespace

class Pipeline::Impl {
 public:
  Impl(Registry registry, GraphSpec spec, ValidatedGraph graph, const PipelineOptions& options)
      : registry_(std::move(registry)), spec_(std::move(spec)), graph_(std::move(graph)) {
    Diagnostics diagnostics;
    plan(options, diagnostics);
    if (diagnostics.has_errors()) throw_graph_error(diagnostics);
    create_and_open();
  }

  ~Impl() {
    if (!closed_) (void)close_all();
  }

  // Loads the plugins the graph may need, checks the graph against them and plans the run.
  static std::unique_ptr<Impl> create(GraphSpec spec, Diagnostics& diagnostics,
                                      const PipelineOptions& options) {
    if (options.keep_frame_buffers_mapped) keep_frame_buffers_mapped();
    Registry registry = load_registry(options.plugin_paths, spec.plugin_paths);
    ValidatedGraph graph = validate_graph(spec, registry, diagnostics);
    if (diagnostics.has_errors()) throw_graph_error(diagnostics);
    return std::make_unique<Impl>(std::move(registry), std::move(spec), std::move(graph), options);
  }

  const std::string& name() const { return graph_.name; }
  const std::vector<PortInfo>& inputs() const { return input_info_; }
  const std::vector<PortInfo>& outputs() const { return output_info_; }

  std::vector<std::string> nodes() const {
    std::vector<std::string> ids;
    for (const auto& node : nodes_)
      ids.push_back(node->spec->id);
    return ids;
  }

  FrameResult process(const std::map<std::string, Packet, std::less<>>& inputs) {
    if (closed_) throw std::logic_error("pipeline '" + graph_.name + "' is closed");
    check_inputs(inputs);
    for (const auto& port : graph_.inputs) {
      fed_[port.port.from_node][port.port.from_port] = inputs.find(port.name)->second;
    }

    FrameResult result;
    result.frame_index = frame_;
    std::string stem;
    const auto outputs_of = [&](std::size_t graph_index) {
      return std::span<const Packet>(outputs_of_node(graph_index));
    };
    for (auto& node : nodes_) {
      ProcessContext& ctx = *node->ctx;
      ctx.begin_frame(frame_);
      if (!detail::gather_inputs(*node->spec, ctx, outputs_of)) continue;
      const auto start = detail::Clock::now();
      try {
        detail::call_stage(*node->instance.stage, ctx, *node->spec, stem);
      } catch (const RunError& error) {
        throw ProcessError(error.what());
      }
      result.timings.push_back({node->spec->id, detail::ms_between(start, detail::Clock::now())});
      for (const auto& warning : ctx.warnings()) {
        result.warnings.push_back("node '" + node->spec->id + "', frame " + std::to_string(frame_) +
                                  ": " + warning);
      }
      if (node->spec->stage->spec.is_source()) {
        if (ctx.at_end_of_stream()) {
          result.end_of_stream = true;
          return result;
        }
        const FrameInfo* info = stem.empty() ? detail::frame_of(ctx.outputs()) : nullptr;
        if (info != nullptr) stem = info->stem;
      }
    }
    for (const auto& port : graph_.outputs) {
      result.outputs[port.name] = outputs_of_node(port.port.from_node)[port.port.from_port];
    }
    ++frame_;
    return result;
  }

  void close() {
    if (closed_) return;
    const std::string error = close_all();
    if (!error.empty()) throw ProcessError(error);
  }

 private:
  struct Node {
    detail::StageInstance instance;
    const ValidatedNode* spec = nullptr;
    std::unique_ptr<ProcessContext> ctx;
  };

  // Which nodes run: every node a graph output needs (or every node, with run_sinks), except the
  // producers of the graph inputs, whose outputs the host provides.
  void plan(const PipelineOptions& options, Diagnostics& diagnostics) {
    const std::size_t count = graph_.nodes.size();
    std::vector<bool> fed(count, false);
    for (const auto& port : graph_.inputs) {
      fed[port.port.from_node] = true;
      input_info_.push_back({port.name, port.type_key});
    }
    for (const auto& port : graph_.outputs)
      output_info_.push_back({port.name, port.type_key});

    std::vector<bool> runs(count, options.run_sinks);
    if (!options.run_sinks) {
      if (graph_.outputs.empty()) {
        diagnostics.error({spec_.file.string(), 0, 0},
                          "graph '" + graph_.name +
                              "' declares no 'outputs:', so a program has nothing to read; "
                              "declare them (docs/embedding.md) or run its sinks (run_sinks)");
      }
      // Producers come before consumers: walking backwards, a node runs when a running node (or
      // a graph output) reads it.
      for (const auto& port : graph_.outputs)
        runs[port.port.from_node] = true;
      for (std::size_t i = count; i-- > 0;) {
        if (!runs[i]) continue;
        for (const auto& input : graph_.nodes[i].inputs) {
          if (input) runs[input->from_node] = true;
        }
      }
    }
    for (std::size_t i = 0; i < count; ++i) {
      if (fed[i]) runs[i] = false;
    }
    check_fed_ports(fed, runs, diagnostics);

    fed_.resize(count);
    index_of_.assign(count, kNotRun);
    for (std::size_t i = 0; i < count; ++i) {
      if (fed[i]) fed_[i].resize(graph_.nodes[i].stage->spec.outputs().size());
      if (!runs[i]) continue;
      index_of_[i] = nodes_.size();
      auto node = std::make_unique<Node>();
      node->spec = &graph_.nodes[i];
      nodes_.push_back(std::move(node));
    }
  }

  // A running node that reads an output of a node the host replaces must read a graph input:
  // the other outputs of that node are never made.
  void check_fed_ports(const std::vector<bool>& fed, const std::vector<bool>& runs,
                       Diagnostics& diagnostics) const {
    const auto is_graph_input = [&](const Connection& c) {
      return std::any_of(graph_.inputs.begin(), graph_.inputs.end(), [&](const auto& port) {
        return port.port.from_node == c.from_node && port.port.from_port == c.from_port;
      });
    };
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i) {
      if (!runs[i]) continue;
      const ValidatedNode& node = graph_.nodes[i];
      for (std::size_t port = 0; port < node.inputs.size(); ++port) {
        const auto& input = node.inputs[port];
        if (!input || !fed[input->from_node] || is_graph_input(*input)) continue;
        const ValidatedNode& producer = graph_.nodes[input->from_node];
        diagnostics.error(node.where,
                          "node " + in_quotes(node.id) + " reads " +
                              in_quotes(producer.id + "." +
                                        producer.stage->spec.outputs()[input->from_port].name) +
                              ", but node " + in_quotes(producer.id) +
                              " is not run: the host feeds its graph inputs; declare that port "
                              "a graph input too");
      }
    }
  }

  void create_and_open() {
    for (auto& node : nodes_) {
      try {
        node->instance = detail::create_stage(*node->spec);
      } catch (const RunError& error) {
        throw ProcessError(error.what());
      }
      node->ctx = std::make_unique<ProcessContext>(node->spec->stage->spec, node->spec->id);
    }
    for (auto& node : nodes_) {
      try {
        detail::open_stage(node->instance, *node->spec);
      } catch (const RunError& error) {
        (void)close_all();
        throw ProcessError(error.what());
      }
    }
  }

  void check_inputs(const std::map<std::string, Packet, std::less<>>& inputs) const {
    for (const auto& [input_name, packet] : inputs) {
      // A named reference: clang 14 cannot capture a structured binding in a lambda.
      const std::string& name = input_name;
      const auto port = std::find_if(graph_.inputs.begin(), graph_.inputs.end(),
                                     [&name](const auto& p) { return p.name == name; });
      if (port == graph_.inputs.end()) {
        std::vector<std::string> names;
        for (const auto& p : graph_.inputs)
          names.push_back(p.name);
        throw std::invalid_argument(
            "graph '" + graph_.name + "' has no input " + in_quotes(name) +
            (names.empty() ? std::string("; it declares no inputs (it reads its own source)")
                           : "; its inputs are " + quoted_list(names)));
      }
      if (packet.empty()) {
        throw std::invalid_argument("graph input " + in_quotes(name) + " is empty");
      }
      if (packet.type_key() != port->type_key) {
        throw std::invalid_argument("graph input " + in_quotes(name) + " takes " + port->type_key +
                                    ", got " + std::string(packet.type_key()));
      }
      if (std::string error = packet.format_error(); !error.empty()) {
        throw std::invalid_argument("graph input " + in_quotes(name) + " (" + port->type_key +
                                    "): " + error);
      }
    }
    for (const auto& port : graph_.inputs) {
      if (inputs.find(port.name) == inputs.end()) {
        throw std::invalid_argument("graph input " + in_quotes(port.name) + " (" + port.type_key +
                                    ") is missing");
      }
    }
  }

  static std::string quoted_list(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& name : names)
      out += (out.empty() ? "'" : ", '") + name + "'";
    return out;
  }

  std::span<const Packet> outputs_of_node(std::size_t graph_index) const {
    if (!fed_[graph_index].empty()) return fed_[graph_index];
    const std::size_t index = index_of_[graph_index];
    if (index == kNotRun) return {};
    return nodes_[index]->ctx->outputs();
  }

  std::string close_all() noexcept {
    closed_ = true;
    std::string first_error;
    for (auto it = nodes_.rbegin(); it != nodes_.rend(); ++it) {
      std::string error = detail::close_stage((*it)->instance, *(*it)->spec);
      if (first_error.empty()) first_error = std::move(error);
    }
    return first_error;
  }

  static constexpr std::size_t kNotRun = static_cast<std::size_t>(-1);

  // Declared first so that they are destroyed last: the stages' code lives in the plugins the
  // registry holds, and the validated graph points into the registry.
  Registry registry_;
  GraphSpec spec_;
  ValidatedGraph graph_;
  std::vector<PortInfo> input_info_;
  std::vector<PortInfo> output_info_;
  std::vector<std::unique_ptr<Node>> nodes_;  // the nodes that run, in execution order
  std::vector<std::size_t> index_of_;         // graph node index -> index into nodes_, or kNotRun
  std::vector<std::vector<Packet>> fed_;      // per graph node: the host's packets, if it feeds it
  std::int64_t frame_ = 0;
  bool closed_ = false;
};

namespace {

LoadOptions load_options(const PipelineOptions& options) {
  LoadOptions load;
  load.params = options.params;
  load.sets = options.sets;
  load.variant = options.variant;
  return load;
}

}  // namespace

Pipeline::Pipeline(const fs::path& graph_file, const PipelineOptions& options) {
  Diagnostics diagnostics;
  GraphSpec spec = load_graph_file(graph_file, load_options(options), diagnostics);
  impl_ = Impl::create(std::move(spec), diagnostics, options);
}

Pipeline::Pipeline(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Pipeline Pipeline::from_text(const std::string& yaml, const fs::path& display_name,
                             const PipelineOptions& options) {
  Diagnostics diagnostics;
  GraphSpec spec = load_graph_text(yaml, display_name, load_options(options), diagnostics);
  return Pipeline(Impl::create(std::move(spec), diagnostics, options));
}

Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

const std::string& Pipeline::name() const {
  return impl_->name();
}
const std::vector<PortInfo>& Pipeline::inputs() const {
  return impl_->inputs();
}
const std::vector<PortInfo>& Pipeline::outputs() const {
  return impl_->outputs();
}
std::vector<std::string> Pipeline::nodes() const {
  return impl_->nodes();
}
FrameResult Pipeline::process(const std::map<std::string, Packet, std::less<>>& inputs) {
  return impl_->process(inputs);
}
void Pipeline::close() {
  impl_->close();
}

std::vector<StageSummary> list_stages(const std::vector<fs::path>& plugin_paths) {
  const Registry registry = load_registry(plugin_paths, {});
  std::vector<StageSummary> stages;
  for (const auto& name : registry.stage_names()) {
    const StageEntry* entry = registry.find(name);
    const std::string& doc = entry->spec.doc();
    stages.push_back({name, entry->plugin ? entry->plugin->name : std::string("builtin"),
                      doc.substr(0, doc.find('\n'))});
  }
  return stages;
}

std::string inspect_stage(const std::string& name, const std::vector<fs::path>& plugin_paths) {
  const Registry registry = load_registry(plugin_paths, {});
  const StageEntry* entry = registry.find(name);
  if (entry == nullptr) {
    const std::string suggestion = did_you_mean(name, registry.stage_names());
    throw std::invalid_argument("unknown stage '" + name + "'" +
                                (suggestion.empty() ? "" : "; did you mean '" + suggestion + "'?"));
  }
  std::ostringstream text;
  write_stage_text(text, *entry);
  return text.str();
}

}  // namespace facet
