// The partition plugin: blobs and surface patches into objects (paper sec. II-B f, and the
// authors' later convex-junction merging and surface-patch graph as alternatives).
#include "facet/plugin.hpp"

#include "partition/bsp_stage.hpp"
#include "partition/convex_stage.hpp"
#include "partition/graph_stage.hpp"
#include "partition/patch_graph_sink.hpp"

FACET_PLUGIN("facet_partition", "0.1.0") {
  registrar.add<facet::partition::PartitionBsp>();
  registrar.add<facet::partition::PartitionConvex>();
  registrar.add<facet::partition::PartitionGraph>();
  registrar.add<facet::partition::PatchGraphSink>();
}
