// The grow plugin: region growing of surface patches (paper sec. II-A c).
#include "facet/plugin.hpp"

#include "grow/grow_surfaces.hpp"

FACET_PLUGIN("facet_grow", "0.1.0") {
  registrar.add<facet::grow::GrowSurfaces>();
}
