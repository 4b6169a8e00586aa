// The blobs plugin: Euclidean object blobs (paper sec. II-B e).
#include "facet/plugin.hpp"

#include "blobs/grow_blobs.hpp"

FACET_PLUGIN("facet_blobs", "0.1.0") {
  registrar.add<facet::blobs::GrowBlobs>();
}
