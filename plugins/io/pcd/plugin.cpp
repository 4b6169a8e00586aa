// The pcd plugin: organized PCD files (Point Cloud Library format) as depth frames.
#include "facet/plugin.hpp"

#include "pcd/pcd_source.hpp"

FACET_PLUGIN("facet_pcd", "0.1.0") {
  registrar.add<facet::pcd::PcdSource>();
}
