// load_plugin() / load_plugins(): open plugin files, check their header, register their stages.

#include "facet/framework/plugin_loader.hpp"

#include <dlfcn.h>

#include <boost/dll/shared_library.hpp>
#include <exception>
#include <memory>
#include <set>
#include <string>

#include "elf_check.hpp"
#include "facet/plugin.hpp"
#include "plugin_files.hpp"
#include "plugin_header_check.hpp"

namespace facet {

namespace fs = std::filesystem;

namespace {

using Library = boost::dll::shared_library;

// RTLD_NOW: an undefined symbol is reported now, naming the file, not later as a crash in the
// middle of a run. RTLD_LOCAL: two plugins may use the same internal symbol names.
// RTLD_NODELETE: a plugin's code and string literals (type keys, factories) stay mapped until
// exit, whatever order the registry, stage instances and packets are destroyed in.
const boost::dll::load_mode::type kLoadMode =
    boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local |
    static_cast<boost::dll::load_mode::type>(RTLD_NODELETE);

struct Opened {
  std::shared_ptr<Library> library;
  std::string error;
};

Opened open_library(const fs::path& file) {
  Opened result;
  if (const auto refused = detail::check_elf_file(file)) {
    result.error = "cannot load: " + file.string() + ": " + *refused;
    return result;
  }
  auto library = std::make_shared<Library>();
  boost::dll::fs::error_code ec;
  library->load(boost::dll::fs::path(file.native()), kLoadMode, ec);
  if (!ec) {
    result.library = std::move(library);
    return result;
  }
  // Boost.DLL reduces a failed dlopen() to "bad file descriptor"; what went wrong (an undefined
  // symbol, a missing dependency, not an ELF file) is only in dlerror(), which nothing has
  // reset since the failed call.
  const char* reason = dlerror();
  result.error = reason != nullptr ? reason : ec.message();
  if (result.error.find(file.filename().string()) == std::string::npos) {
    result.error = file.string() + ": " + result.error;
  }
  result.error = "cannot load: " + result.error;
  return result;
}

class LoadAttempt {
 public:
  LoadAttempt(fs::path file, Registry& registry) : file_(std::move(file)), registry_(registry) {}

  bool run() {
    auto opened = open_library(file_);
    if (!opened.library) return fail(opened.error);
    const auto& library = *opened.library;
    if (!library.has(FACET_PLUGIN_ENTRY_NAME)) {
      return fail("not a facet plugin: no exported symbol '" FACET_PLUGIN_ENTRY_NAME "'");
    }
    const facet_plugin_header* header =
        library.get<const facet_plugin_header*()>(FACET_PLUGIN_ENTRY_NAME)();
    if (header == nullptr) return fail("'" FACET_PLUGIN_ENTRY_NAME "' returned no header");
    if (auto refused = detail::check_plugin_header(*header)) return fail(*refused);

    // Only now is the plugin's C++ trusted enough to be called. `stages` also collects the
    // plugin's `facet doctor` sections.
    StageList stages;
    try {
      header->register_stages(static_cast<Registrar*>(&stages));
    } catch (const std::exception& error) {
      return fail(std::string("registering stages failed: ") + error.what());
    } catch (...) {
      return fail("registering stages failed: unknown exception");
    }

    auto info = std::make_shared<PluginInfo>();
    info->file = file_;
    info->name = header->plugin_name;
    info->version = header->plugin_version != nullptr ? header->plugin_version : "";
    info->sdk_version = detail::plugin_sdk_version(*header);
    info->toolchain = header->toolchain;
    for (const auto& spec : stages.stages())
      info->stages.push_back(spec.name());
    // Every stage entry holds the library, so the plugin outlives the instances it creates.
    std::shared_ptr<const void> pin = std::move(opened.library);
    registry_.add_plugin(std::move(info), stages.stages(), std::move(pin), stages.diagnostics());
    return true;
  }

 private:
  bool fail(std::string reason) {
    registry_.add_failure({file_, std::move(reason)});
    return false;
  }

  fs::path file_;
  Registry& registry_;
};

}  // namespace

bool load_plugin(const fs::path& file, Registry& registry) {
  try {
    return LoadAttempt(file, registry).run();
  } catch (const std::exception& error) {
    // Out of memory, file system errors: still a failure of this one file, never of the host.
    registry.add_failure({file, std::string("cannot load: ") + error.what()});
  } catch (...) {
    registry.add_failure({file, "cannot load: unknown error"});
  }
  return false;
}

void load_plugins(const std::vector<SearchDir>& dirs, Registry& registry) {
  // A file name seen in an earlier directory shadows the same name later on, as PATH does.
  std::set<fs::path> seen_names;
  for (const auto& search_dir : dirs) {
    for (const auto& file : detail::plugin_files_in(search_dir.dir)) {
      if (seen_names.insert(file.filename()).second) load_plugin(file, registry);
    }
  }
}

}  // namespace facet
