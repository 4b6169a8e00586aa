// The shape plugin: per-object shape models for grasping (paper sec. III-E).
#include "facet/plugin.hpp"

#include "shape/pca_box_stage.hpp"
#include "shape/superquadric_stage.hpp"

FACET_PLUGIN("facet_shape", "0.1.0") {
  registrar.add<facet::shape::PcaBoxStage>();
  registrar.add<facet::shape::SuperquadricStage>();
}
