#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "facet/framework/plugin_loader.hpp"
#include "facet/sdk_version.h"
#include "facet/version.hpp"
#include "session.hpp"

namespace facet::cli {
namespace {

// The text of one plugin section; a section that throws prints its message instead, so one
// broken driver stack never hides the rest of the report.
std::string section_text(const DiagnosticSection& section) {
  try {
    return section.report ? section.report() : std::string("(no report)");
  } catch (const std::exception& error) {
    return std::string("error: ") + error.what();
  } catch (...) {
    return "error: unknown exception";
  }
}

void print_plugin_sections(const Registry& registry, std::ostream& out) {
  for (const auto& entry : registry.diagnostics()) {
    out << "\n" << entry.section.title << " (from plugin " << entry.plugin->name << "):\n";
    std::istringstream lines(section_text(entry.section));
    std::string line;
    bool any = false;
    while (std::getline(lines, line)) {
      out << "  " << line << "\n";
      any = true;
    }
    if (!any) out << "  (nothing to report)\n";
  }
}

}  // namespace

void add_doctor_command(CLI::App& app, int& exit_code) {
  auto plugins = std::make_shared<PluginOptions>();
  CLI::App* command = app.add_subcommand(
      "doctor",
      "Show plugin search paths, plugins found, load failures, ABI fingerprints and what "
      "plugins report of their drivers and devices");
  add_plugin_options(*command, *plugins);
  command->callback([plugins, &exit_code] {
    std::cout << "facet " << FACET_SDK_VERSION_STRING << "\n";
    std::cout << "host: plugin ABI " << FACET_PLUGIN_ABI_VERSION << ", SDK "
              << FACET_SDK_VERSION_STRING << ", toolchain " << sdk_toolchain_fingerprint() << "\n";

    const auto dirs = plugin_search_dirs(plugins->plugin_paths, plugin_path_environment(), {});
    std::cout << "\nplugin search path (in order):\n";
    int position = 1;
    for (const auto& dir : dirs) {
      std::error_code ec;
      const bool exists = std::filesystem::is_directory(dir.dir, ec);
      std::cout << "  " << position++ << ". " << dir.dir.string() << "  [" << dir.origin << "]"
                << (exists ? "" : "  (missing)") << "\n";
    }
    std::cout << "  (graph files may add directories with plugins.paths, searched after "
                 "FACET_PLUGIN_PATH)\n";

    Registry registry;
    load_plugins(dirs, registry);
    std::cout << "\nplugins loaded:" << (registry.plugins().empty() ? " none\n" : "\n");
    for (const auto& plugin : registry.plugins()) {
      std::cout << "  " << plugin->name << " " << plugin->version << "  " << plugin->file.string()
                << "\n      SDK " << plugin->sdk_version << ", toolchain " << plugin->toolchain
                << ", " << plugin->stages.size() << " stage(s):";
      for (const auto& stage : plugin->stages)
        std::cout << " " << stage;
      std::cout << "\n";
    }
    std::cout << "\nload failures:" << (registry.failures().empty() ? " none\n" : "\n");
    for (const auto& failure : registry.failures()) {
      std::cout << "  " << failure.file.string() << "\n      " << failure.reason << "\n";
    }
    print_plugin_sections(registry, std::cout);
    exit_code = registry.failures().empty() ? kOk : kPluginFailure;
  });
}

}  // namespace facet::cli
