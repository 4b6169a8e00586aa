#include "facet/framework/registry.hpp"

#include <algorithm>

#include "facet/version.hpp"

namespace facet {

void Registry::add_plugin(std::shared_ptr<const PluginInfo> plugin,
                          const std::vector<StageSpec>& stages, std::shared_ptr<const void> library,
                          const std::vector<DiagnosticSection>& diagnostics) {
  for (const auto& spec : stages) {
    const auto it = stages_.find(spec.name());
    if (it != stages_.end()) {
      const auto describe = [](const PluginInfo& p) {
        return p.file.empty() ? p.name + " (built in)" : p.file.string();
      };
      failures_.push_back(
          {plugin->file, "stage '" + spec.name() +
                             "' is provided by two plugins: " + describe(*it->second.plugin) +
                             " and " + describe(*plugin) + "; the second was ignored"});
      continue;
    }
    stages_.emplace(spec.name(), StageEntry{library, spec, plugin});
  }
  for (const auto& section : diagnostics)
    diagnostics_.push_back({library, section, plugin});
  plugins_.push_back(std::move(plugin));
}

void Registry::add_builtin(const std::vector<StageSpec>& stages) {
  auto info = std::make_shared<PluginInfo>();
  info->name = "builtin";
  info->version = FACET_SDK_VERSION_STRING;
  info->sdk_version = FACET_SDK_VERSION_STRING;
  info->toolchain = sdk_toolchain_fingerprint();
  for (const auto& spec : stages)
    info->stages.push_back(spec.name());
  add_plugin(std::move(info), stages, nullptr);
}

const StageEntry* Registry::find(std::string_view stage_name) const {
  const auto it = stages_.find(stage_name);
  return it == stages_.end() ? nullptr : &it->second;
}

std::vector<std::string> Registry::stage_names() const {
  std::vector<std::string> names;
  names.reserve(stages_.size());
  for (const auto& [name, entry] : stages_)
    names.push_back(name);
  return names;  // std::map keeps them sorted
}

}  // namespace facet
