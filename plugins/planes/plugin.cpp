// The planes plugin: support and background planes (paper sec. II-B d).
#include "facet/plugin.hpp"

#include "planes/support_planes.hpp"

FACET_PLUGIN("facet_planes", "0.1.0") {
  registrar.add<facet::planes::SupportPlaneStage>();
}
