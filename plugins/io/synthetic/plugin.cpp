// The synthetic plugin: generated table-top scenes with ground truth, for tests and benchmarks.
#include "facet/plugin.hpp"

#include "synthetic/synthetic_source.hpp"

FACET_PLUGIN("facet_synthetic", "0.1.0") {
  registrar.add<facet::synthetic::SyntheticSource>();
}
