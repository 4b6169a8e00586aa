// The convert plugin: stages that change how depth is represented, without changing what it says.
#include "facet/plugin.hpp"

#include "convert/points_stage.hpp"

FACET_PLUGIN("facet_convert", "0.1.0") {
  registrar.add<facet::convert::PointsStage>();
}
