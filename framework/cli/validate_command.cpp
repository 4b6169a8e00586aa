#include <iostream>
#include <memory>
#include <string>
#include <vector>

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
  CLI::App* command = app.add_subcommand(
      "validate",
      "Check a graph and every variant it defines (or only --variant) without running it; "
      "print every error");
  add_graph_options(*command, args->graph);
  add_plugin_options(*command, args->plugins);
  command->callback([args, &exit_code] {
    const auto loaded = load_and_validate(args->plugins, args->graph, ConstructStages::yes);
    exit_code = loaded->exit_code;
    // Without --variant every variant is checked too: `compare` and `run --variant` take them,
    // and a variant's `set:` or `replace:` can be wrong while the base graph is fine. (When the
    // base graph is broken its errors would only repeat once per variant.)
    std::vector<std::string> valid_variants;
    if (args->graph.variant.empty() && exit_code == kOk) {
      for (const VariantCheck& check :
           validate_variants(*loaded, args->plugins, args->graph, ConstructStages::yes)) {
        if (check.exit_code == kOk) {
          valid_variants.push_back(check.variant);
        } else if (exit_code == kOk) {
          exit_code = check.exit_code;
        }
      }
    }
    if (exit_code == kOk) {
      std::cout << args->graph.graph_file.string() << ": graph '" << loaded->graph.name
                << "' is valid (" << loaded->graph.nodes.size() << " nodes"
                << (loaded->spec.variant.empty() ? "" : ", variant " + loaded->spec.variant);
      if (!valid_variants.empty()) {
        std::cout << "; variants";
        for (const std::string& variant : valid_variants)
          std::cout << " " << variant;
        std::cout << " valid too";
      }
      std::cout << ")\n";
    }
  });
}

}  // namespace facet::cli
