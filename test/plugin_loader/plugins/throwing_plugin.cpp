// A plugin whose registration throws, like one that fails to read its own configuration.

#include <facet/plugin.hpp>
#include <stdexcept>

FACET_PLUGIN("throwing", "0.0.1") {
  registrar.add_stage(facet::StageSpec("throwing.half_registered", "Never reaches the registry."));
  throw std::runtime_error("calibration table missing");
}
