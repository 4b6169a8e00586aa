#include <iostream>
#include <memory>
#include <variant>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "facet/framework/diagnostics.hpp"
#include "facet/framework/json_writer.hpp"
#include "facet/framework/stage_catalogue.hpp"
#include "facet/framework/stage_doc.hpp"
#include "session.hpp"
#include "stage_lines.hpp"

namespace facet::cli {
namespace {

// What a name given to `facet inspect` stands for, tried in this order: a stage, a family of
// stages (alternatives for one node, e.g. normals.*), a plugin.
struct StageName {
  const StageEntry* stage;
};
struct FamilyName {
  std::string family;
  std::vector<const StageEntry*> stages;
};
struct PluginName {
  const PluginInfo* plugin;
  std::vector<const StageEntry*> stages;
};
struct UnknownName {};
using Resolved = std::variant<StageName, FamilyName, PluginName, UnknownName>;

Resolved resolve(const Registry& registry, const std::string& name) {
  if (const StageEntry* entry = registry.find(name)) return StageName{entry};
  if (auto stages = stages_of_family(registry, name); !stages.empty())
    return FamilyName{name, std::move(stages)};
  if (const PluginInfo* plugin = find_plugin(registry, name)) {
    std::vector<const StageEntry*> stages;
    for (const auto& stage : plugin->stages) {
      if (const StageEntry* entry = registry.find(stage)) stages.push_back(entry);
    }
    return PluginName{plugin, std::move(stages)};
  }
  return UnknownName{};
}

void write_family_text(std::ostream& out, const FamilyName& family) {
  out << family.family << ": " << family.stages.size()
      << (family.stages.size() == 1 ? " stage" : " stages")
      << ", alternatives for one node (`facet inspect NAME` documents one)\n";
  write_stage_lines(out, family.stages, "  ");
}

void write_plugin_text(std::ostream& out, const PluginName& found) {
  const PluginInfo& plugin = *found.plugin;
  out << "plugin " << plugin.name << " " << plugin.version << "\n";
  out << "  file:      " << (plugin.file.empty() ? "(built in)" : plugin.file.string()) << "\n";
  out << "  sdk:       " << plugin.sdk_version << "\n";
  out << "  toolchain: " << plugin.toolchain << "\n";
  out << "\nstages:" << (found.stages.empty() ? " none\n" : "\n");
  write_stage_lines(out, found.stages, "  ");
}

// The stages a name stands for, for --markdown and --json, which document stages one by one.
std::vector<const StageEntry*> stages_of(const Resolved& resolved) {
  if (const auto* stage = std::get_if<StageName>(&resolved)) return {stage->stage};
  if (const auto* family = std::get_if<FamilyName>(&resolved)) return family->stages;
  if (const auto* plugin = std::get_if<PluginName>(&resolved)) return plugin->stages;
  return {};
}

}  // namespace

void add_inspect_command(CLI::App& app, int& exit_code) {
  struct Args {
    PluginOptions plugins;
    std::vector<std::string> names;
    bool all = false;
    bool markdown = false;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(
      "inspect",
      "Document a stage (ports, types, parameters with defaults, ranges, units), a family of "
      "stages (normals) or a plugin (facet_normals)");
  command->add_option("name", args->names,
                      "Stage (filter.median), stage family (normals) or plugin (facet_normals)");
  command->add_flag("--all", args->all, "Document every stage found");
  auto* markdown =
      command->add_flag("--markdown", args->markdown, "Write Markdown (for docs/) instead of text");
  command
      ->add_flag("--json", args->json,
                 "Write JSON for tools: one stage's spec as an object; an array of specs for a "
                 "family, a plugin, several names or --all")
      ->excludes(markdown);
  add_plugin_options(*command, args->plugins);
  command->callback([args, &exit_code] {
    const Registry registry = load_registry(args->plugins, {});
    if (!args->all && args->names.empty()) {
      std::cerr << "error: name a stage, a family or a plugin, or give --all (see `facet list`)\n";
      exit_code = kUsage;
      return;
    }
    exit_code = kOk;
    std::vector<Resolved> resolved;
    if (args->all) {
      for (const auto& name : registry.stage_names())
        resolved.push_back(StageName{registry.find(name)});
    }
    for (const auto& name : args->names) {
      resolved.push_back(resolve(registry, name));
      if (!std::holds_alternative<UnknownName>(resolved.back())) continue;
      std::cerr << "error: no stage, stage family or plugin named '" << name << "'"
                << did_you_mean_text(
                       closest_catalogue_names(registry, name, 3, CatalogueNames::inspectable))
                << "\n";
      for (const auto& failure : registry.failures()) {
        std::cerr << "note: a plugin failed to load and may provide it: " << failure.file.string()
                  << ": " << failure.reason << "\n";
      }
      exit_code = registry.failures().empty() ? kUsage : kPluginFailure;
    }

    if (args->json) {
      std::vector<const StageEntry*> stages;
      for (const auto& r : resolved) {
        for (const StageEntry* entry : stages_of(r))
          stages.push_back(entry);
      }
      // One stage asked for by name: its object. Anything that may stand for several: an array,
      // even when it holds one stage, so that a tool knows the shape from its own command line.
      const bool single = !args->all && args->names.size() == 1 &&
                          std::holds_alternative<StageName>(resolved.front());
      JsonWriter json(std::cout);
      if (single) {
        write_stage_json(json, *stages.front());
        return;
      }
      if (exit_code != kOk) return;  // no half answer a tool might take for the whole
      json.begin_array();
      for (const StageEntry* entry : stages)
        write_stage_json(json, *entry);
      json.end_array();
      std::cout << "\n";
      return;
    }

    bool first = true;
    for (const auto& r : resolved) {
      if (std::holds_alternative<UnknownName>(r)) continue;
      if (args->markdown) {  // every stage documented in full, as docs/ wants it
        for (const StageEntry* entry : stages_of(r))
          write_stage_markdown(std::cout, *entry);
        continue;
      }
      if (!first) std::cout << "\n";
      first = false;
      if (const auto* stage = std::get_if<StageName>(&r))
        write_stage_text(std::cout, *stage->stage);
      if (const auto* family = std::get_if<FamilyName>(&r)) write_family_text(std::cout, *family);
      if (const auto* plugin = std::get_if<PluginName>(&r)) write_plugin_text(std::cout, *plugin);
    }
  });
}

}  // namespace facet::cli
