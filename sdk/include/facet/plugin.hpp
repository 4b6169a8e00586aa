#pragma once
// Declaring a plugin: one FACET_PLUGIN block per shared library.
//
//   FACET_PLUGIN("my_plugin", "1.0.0") {
//     registrar.add<MyStage>();
//   }
//
// The macro exports the single C entry symbol (see plugin_abi.h) with this SDK's version and
// toolchain fingerprint; the host checks them before it runs the block.
//
// A plugin that talks to hardware or system libraries may also add a section to `facet doctor`:
//
//   registrar.add_diagnostic("OpenNI2", [] { return list_drivers_and_devices(); });

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "facet/plugin_abi.h"
#include "facet/stage.hpp"
#include "facet/version.hpp"

namespace facet {

// Produces the text of one `facet doctor` section. Called only by `facet doctor`, never while
// plugins load, so probing devices or drivers costs nothing in `facet run`. May throw: the host
// prints the message in the section instead.
using DiagnosticReport = std::function<std::string()>;

struct DiagnosticSection {
  std::string title;  // e.g. "OpenNI2"
  DiagnosticReport report;
};

// What a plugin's FACET_PLUGIN block talks to. Its virtual functions are part of the plugin ABI
// (FACET_PLUGIN_ABI_VERSION): a function is only ever appended, and the version bumped.
class Registrar {
 public:
  virtual ~Registrar() = default;

  template <class StageT>
  void add() {
    StageSpec spec = StageT::spec();
    spec.factory([](const Params& params) -> std::unique_ptr<Stage> {
      return std::make_unique<StageT>(params);
    });
    add_stage(std::move(spec));
  }

  virtual void add_stage(StageSpec spec) = 0;

  // Adds a section titled `title` to `facet doctor` (since plugin ABI 2). `report` runs in the
  // host, with the plugin loaded, each time doctor prints.
  virtual void add_diagnostic(std::string title, DiagnosticReport report) = 0;
};

// Collects stages and diagnostic sections in memory: used by the plugin loader, StageRunner and
// tests that need no plugin file.
class StageList final : public Registrar {
 public:
  void add_stage(StageSpec spec) override { stages_.push_back(std::move(spec)); }
  void add_diagnostic(std::string title, DiagnosticReport report) override {
    diagnostics_.push_back({std::move(title), std::move(report)});
  }
  const std::vector<StageSpec>& stages() const { return stages_; }
  const std::vector<DiagnosticSection>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<StageSpec> stages_;
  std::vector<DiagnosticSection> diagnostics_;
};

}  // namespace facet

#if defined(_WIN32)
#define FACET_PLUGIN_EXPORT __declspec(dllexport)
#else
#define FACET_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

#define FACET_PLUGIN(plugin_name_literal, plugin_version_literal)                      \
  static void facet_plugin_register_(::facet::Registrar& registrar);                   \
  extern "C" FACET_PLUGIN_EXPORT const facet_plugin_header* facet_plugin_entry(void) { \
    static const facet_plugin_header header = {                                        \
        FACET_PLUGIN_MAGIC,                                                            \
        FACET_PLUGIN_ABI_VERSION,                                                      \
        static_cast<uint32_t>(sizeof(facet_plugin_header)),                            \
        FACET_SDK_VERSION_MAJOR,                                                       \
        FACET_SDK_VERSION_MINOR,                                                       \
        FACET_SDK_VERSION_PATCH,                                                       \
        FACET_TOOLCHAIN_FINGERPRINT,                                                   \
        plugin_name_literal,                                                           \
        plugin_version_literal,                                                        \
        [](void* registrar) {                                                          \
          facet_plugin_register_(*static_cast<::facet::Registrar*>(registrar));        \
        }};                                                                            \
    return &header;                                                                    \
  }                                                                                    \
  static void facet_plugin_register_(::facet::Registrar& registrar)
