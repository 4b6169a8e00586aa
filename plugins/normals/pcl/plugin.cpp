// The normals_pcl plugin: PCL's integral-image normal estimation, as a point of comparison.
#include "facet/plugin.hpp"

#include "normals/pcl/integral_stage.hpp"

FACET_PLUGIN("facet_normals_pcl", "0.1.0") {
  registrar.add<facet::normals::IntegralStage>();
}
