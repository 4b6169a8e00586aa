#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "session.hpp"

namespace facet::cli {

void add_validate_command(CLI::App& app, int& exit_code) {
  struct Args {
    PluginOptions plugins;
    GraphOptions graph;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command =
      app.add_subcommand("validate", "Check a graph without running it; print every error");
  add_graph_options(*command, args->graph);
  add_plugin_options(*command, args->plugins);
  command->callback([args, &exit_code] {
    const auto loaded = load_and_validate(args->plugins, args->graph);
    exit_code = loaded->exit_code;
    if (exit_code == kOk) {
      std::cout << args->graph.graph_file.string() << ": graph '" << loaded->graph.name
                << "' is valid (" << loaded->graph.nodes.size() << " nodes"
                << (loaded->spec.variant.empty() ? "" : ", variant " + loaded->spec.variant)
                << ")\n";
    }
  });
}

}  // namespace facet::cli
