// The plugin's single entry point: its name, its version and the stages it provides.
// FACET_PLUGIN also records the SDK version and toolchain, which the host checks first.

#include <facet/plugin.hpp>

#include "counter_source.hpp"
#include "depth_threshold.hpp"

FACET_PLUGIN("template", "0.1.0") {
  registrar.add<facet_template::CounterSource>();
  registrar.add<facet_template::DepthThreshold>();
}
