// A plugin that calls a function defined nowhere. Linked without --no-undefined, so the mistake
// only shows when the file is loaded: with RTLD_NOW that must be at load time, with the name.

#include <facet/plugin.hpp>

extern "C" __attribute__((visibility("default"))) int facet_test_symbol_defined_nowhere();

FACET_PLUGIN("undefined_symbol", "0.0.1") {
  if (facet_test_symbol_defined_nowhere() == 1) registrar.add_stage(facet::StageSpec("x.y", "z"));
}
