// The edges plugin: surface-normal edge detection (paper sec. II-A b).
#include "facet/plugin.hpp"

#include "edges/edges_avg.hpp"
#include "edges/edges_max.hpp"

FACET_PLUGIN("facet_edges", "0.1.0") {
  registrar.add<facet::edges::MaxNormalEdges>();
  registrar.add<facet::edges::AvgNormalEdges>();
}
