#pragma once
// The bundled plugins of this build (FACET_PLUGIN_DIR), loaded once per test program, for tests
// that run shipped graphs through the framework as `facet run` does.

#include "facet/framework/plugin_loader.hpp"
#include "facet/framework/registry.hpp"

namespace facet::test {

inline const Registry& bundled_plugins() {
  static const Registry registry = [] {
    Registry loaded;
    load_plugins({{FACET_PLUGIN_DIR, "build"}}, loaded);
    return loaded;
  }();
  return registry;
}

}  // namespace facet::test
