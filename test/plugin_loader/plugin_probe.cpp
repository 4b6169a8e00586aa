// facet_plugin_probe FILE...: loads each plugin file and prints its stages or why it failed.

#include <cstdio>
#include <filesystem>

#include "facet/framework/plugin_loader.hpp"
#include "facet/framework/registry.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s PLUGIN_FILE...\n", argv[0]);
    return 2;
  }
  facet::Registry registry;
  for (int i = 1; i < argc; ++i)
    facet::load_plugin(argv[i], registry);
  for (const auto& plugin : registry.plugins()) {
    std::printf("plugin %s %s (sdk %s, %s) from %s\n", plugin->name.c_str(),
                plugin->version.c_str(), plugin->sdk_version.c_str(), plugin->toolchain.c_str(),
                plugin->file.c_str());
  }
  for (const auto& name : registry.stage_names()) {
    std::printf("stage %s: %s\n", name.c_str(), registry.find(name)->spec.summary().c_str());
  }
  for (const auto& failure : registry.failures()) {
    std::fprintf(stderr, "error: %s: %s\n", failure.file.c_str(), failure.reason.c_str());
  }
  return registry.failures().empty() ? 0 : 4;
}
