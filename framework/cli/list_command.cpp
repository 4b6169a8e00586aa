#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "session.hpp"

namespace facet::cli {

void add_list_command(CLI::App& app, int& exit_code) {
  auto plugins = std::make_shared<PluginOptions>();
  CLI::App* command =
      app.add_subcommand("list", "List the stages of every plugin found, and load failures");
  add_plugin_options(*command, *plugins);
  command->callback([plugins, &exit_code] {
    const Registry registry = load_registry(*plugins, {});
    std::size_t width = 0;
    for (const auto& name : registry.stage_names())
      width = std::max(width, name.size());
    for (const auto& name : registry.stage_names()) {
      const StageEntry& entry = *registry.find(name);
      std::cout << fmt::format("{:<{}}  {:<16} {}\n", name, width, entry.plugin->name,
                               entry.spec.summary());
    }
    if (registry.stage_names().empty()) {
      std::cout << "no stages found; `facet doctor` shows where plugins were searched\n";
    }
    for (const auto& failure : registry.failures()) {
      std::cerr << "error: plugin " << failure.file.string() << ": " << failure.reason << "\n";
    }
    exit_code = kOk;
  });
}

}  // namespace facet::cli
