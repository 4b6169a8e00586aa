#pragma once
// Finding and loading plugin shared libraries.
//
// Search order (first match of a file name wins; later directories holding a plugin file of the
// same name are shadowed, like PATH):
//   1. --plugin-path DIR (repeatable)
//   2. $FACET_PLUGIN_PATH (colon-separated)
//   3. `plugins: {paths: [...]}` in the graph file, relative to the graph file
//   4. the build tree / install prefix next to the running executable: <exe
//   dir>/../lib/facet/plugins
//   5. the install prefix the CLI was configured with: <prefix>/lib/facet/plugins

#include <filesystem>
#include <string>
#include <vector>

#include "facet/framework/registry.hpp"

namespace facet {

struct SearchDir {
  std::filesystem::path dir;
  std::string
      origin;  // "--plugin-path", "FACET_PLUGIN_PATH", "graph file", "executable", "install prefix"
};

// The search directories in order, for `facet doctor` and for loading. `environment_value` is the
// value of FACET_PLUGIN_PATH (passed in, so that tests need not touch the environment).
std::vector<SearchDir> plugin_search_dirs(const std::vector<std::filesystem::path>& cli_paths,
                                          const std::string& environment_value,
                                          const std::vector<std::filesystem::path>& graph_paths);

// Loads one plugin file into the registry. Never throws: a failure (unloadable file, missing entry
// symbol, ABI/SDK/toolchain mismatch, exception during registration) is recorded in the registry
// with the file's path and a reason that prints both sides of a mismatch.
bool load_plugin(const std::filesystem::path& file, Registry& registry);

// Loads every plugin file (libfacet_*.so / *.facet.so, see docs/writing-a-plugin.md) found in
// `dirs`, honouring shadowing by file name. Missing directories are skipped silently.
void load_plugins(const std::vector<SearchDir>& dirs, Registry& registry);

}  // namespace facet
