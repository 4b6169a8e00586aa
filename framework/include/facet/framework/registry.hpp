#pragma once
// The stages known to this process: those registered by loaded plugins (and, in tests, those
// registered directly), plus every plugin that failed to load and why.

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "facet/plugin.hpp"
#include "facet/stage_spec.hpp"

namespace facet {

struct PluginInfo {
  std::filesystem::path file;  // empty for stages registered in-process
  std::string name;
  std::string version;
  std::string sdk_version;  // "0.2.0"
  std::string toolchain;    // fingerprint the plugin was built with
  std::vector<std::string> stages;
};

struct LoadFailure {
  std::filesystem::path file;
  std::string reason;
};

struct StageEntry {
  // Keeps the plugin's shared library loaded while a stage made by it exists. Type-erased so
  // that this header does not depend on Boost.DLL. Declared first so that it is destroyed last:
  // `spec` holds a factory whose code lives in the library.
  std::shared_ptr<const void> library;
  StageSpec spec;
  std::shared_ptr<const PluginInfo> plugin;
};

// A section a plugin contributes to `facet doctor` (Registrar::add_diagnostic).
struct DiagnosticEntry {
  // Keeps the plugin loaded while `report`, whose code lives in it, can still be called.
  std::shared_ptr<const void> library;
  DiagnosticSection section;
  std::shared_ptr<const PluginInfo> plugin;
};

class Registry {
 public:
  // Registers every stage of `stages` and every diagnostic section of `diagnostics` as coming
  // from `plugin`. A stage name that is already registered is not replaced: a LoadFailure naming
  // both plugin files is recorded instead.
  void add_plugin(std::shared_ptr<const PluginInfo> plugin, const std::vector<StageSpec>& stages,
                  std::shared_ptr<const void> library,
                  const std::vector<DiagnosticSection>& diagnostics = {});

  // In-process registration, for tests and embedders: plugin name "builtin".
  template <class StageT>
  void add() {
    StageList list;
    list.add<StageT>();
    add_builtin(list.stages());
  }
  void add_builtin(const std::vector<StageSpec>& stages);

  void add_failure(LoadFailure failure) { failures_.push_back(std::move(failure)); }

  const StageEntry* find(std::string_view stage_name) const;
  std::vector<std::string> stage_names() const;  // sorted
  const std::vector<std::shared_ptr<const PluginInfo>>& plugins() const { return plugins_; }
  const std::vector<LoadFailure>& failures() const { return failures_; }
  // In the order the plugins were loaded, and within a plugin in the order it added them.
  const std::vector<DiagnosticEntry>& diagnostics() const { return diagnostics_; }

 private:
  std::map<std::string, StageEntry, std::less<>> stages_;
  std::vector<std::shared_ptr<const PluginInfo>> plugins_;
  std::vector<LoadFailure> failures_;
  std::vector<DiagnosticEntry> diagnostics_;
};

}  // namespace facet
