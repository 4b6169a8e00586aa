#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "facet/framework/stage_catalogue.hpp"
#include "session.hpp"
#include "stage_lines.hpp"

namespace facet::cli {

void add_list_command(CLI::App& app, int& exit_code) {
  struct Args {
    PluginOptions plugins;
    std::string filter;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(
      "list",
      "List the stages of every plugin found (or those matching FILTER), and load failures");
  command->add_option("filter", args->filter,
                      "Only the stages whose name, plugin or summary contain this, ignoring case "
                      "(e.g. normals, facet_io, ground truth)");
  add_plugin_options(*command, args->plugins);
  command->callback([args, &exit_code] {
    const Registry registry = load_registry(args->plugins, {});
    exit_code = kOk;
    const std::vector<const StageEntry*> stages = stages_matching(registry, args->filter);
    write_stage_lines(std::cout, stages);
    if (registry.stage_names().empty()) {
      std::cout << "no stages found; `facet doctor` shows where plugins were searched\n";
    } else if (stages.empty()) {
      // Said on stderr with a usage exit code, so that a script sees that nothing matched.
      std::cerr << "error: no stage's name, plugin or summary contains '" << args->filter << "'"
                << did_you_mean_text(closest_catalogue_names(registry, args->filter, 3,
                                                             CatalogueNames::filter_words))
                << "\n";
      exit_code = registry.failures().empty() ? kUsage : kPluginFailure;
    }
    for (const auto& failure : registry.failures()) {
      std::cerr << "error: plugin " << failure.file.string() << ": " << failure.reason << "\n";
    }
  });
}

}  // namespace facet::cli
