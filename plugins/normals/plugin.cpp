// The normals plugin: surface normals of depth images, the first step of the paper's surface
// patch segmentation. PCL's integral-image normals are a separate plugin (normals_pcl), so this
// one does not depend on PCL.
#include "facet/plugin.hpp"

#include "normals/cross_stage.hpp"
#include "normals/pca_stage.hpp"

FACET_PLUGIN("facet_normals", "0.1.0") {
  registrar.add<facet::normals::CrossStage>();
  registrar.add<facet::normals::PcaStage>();
}
