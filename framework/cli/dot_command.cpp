#include <fstream>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "facet/framework/dot_writer.hpp"
#include "session.hpp"

namespace facet::cli {

void add_dot_command(CLI::App& app, int& exit_code) {
  struct Args {
    PluginOptions plugins;
    GraphOptions graph;
    std::filesystem::path output;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(
      "dot", "Print the graph in Graphviz format (render with: dot -Tsvg -o graph.svg)");
  add_graph_options(*command, args->graph);
  add_plugin_options(*command, args->plugins);
  command->add_option("--output,-o", args->output, "Write to this file instead of stdout");
  command->callback([args, &exit_code] {
    const auto loaded = load_and_validate(args->plugins, args->graph);
    exit_code = loaded->exit_code;
    if (exit_code != kOk) return;
    if (args->output.empty()) {
      write_dot(std::cout, loaded->graph);
      return;
    }
    std::ofstream out(args->output);
    write_dot(out, loaded->graph);
    if (!out) {
      std::cerr << "error: cannot write " << args->output.string() << '\n';
      exit_code = kRuntimeFailure;
    }
  });
}

}  // namespace facet::cli
