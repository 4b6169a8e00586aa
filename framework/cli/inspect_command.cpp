#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "facet/framework/diagnostics.hpp"
#include "facet/framework/stage_doc.hpp"
#include "session.hpp"

namespace facet::cli {

void add_inspect_command(CLI::App& app, int& exit_code) {
  struct Args {
    PluginOptions plugins;
    std::vector<std::string> stages;
    bool all = false;
    bool markdown = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(
      "inspect", "Document a stage: ports, types, parameters with defaults, ranges, units");
  command->add_option("stage", args->stages, "Stage name(s), e.g. filter.median");
  command->add_flag("--all", args->all, "Document every stage found");
  command->add_flag("--markdown", args->markdown, "Write Markdown (for docs/) instead of text");
  add_plugin_options(*command, args->plugins);
  command->callback([args, &exit_code] {
    const Registry registry = load_registry(args->plugins, {});
    const std::vector<std::string> names = args->all ? registry.stage_names() : args->stages;
    if (names.empty()) {
      std::cerr << "error: name a stage, or give --all (see `facet list`)\n";
      exit_code = kUsage;
      return;
    }
    exit_code = kOk;
    bool first = true;
    for (const auto& name : names) {
      const StageEntry* entry = registry.find(name);
      if (entry == nullptr) {
        std::cerr << "error: no stage named '" << name << "'";
        if (const auto guess = did_you_mean(name, registry.stage_names()); !guess.empty()) {
          std::cerr << "; did you mean '" << guess << "'?";
        }
        std::cerr << "\n";
        for (const auto& failure : registry.failures()) {
          std::cerr << "note: a plugin failed to load and may provide it: " << failure.file.string()
                    << ": " << failure.reason << "\n";
        }
        exit_code = registry.failures().empty() ? kUsage : kPluginFailure;
        continue;
      }
      if (!first) std::cout << (args->markdown ? "" : "\n");
      first = false;
      if (args->markdown) {
        write_stage_markdown(std::cout, *entry);
      } else {
        write_stage_text(std::cout, *entry);
      }
    }
  });
}

}  // namespace facet::cli
