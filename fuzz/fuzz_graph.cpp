// A graph file from a stranger: parsed (aliases, duplicate keys, params and their expansion,
// variants and their `extends` chains, --set overrides) and validated against a registry of real
// stages (io's source and sinks), so wiring, types and parameter values are checked too. Errors
// land in the diagnostics; a crash, a hang, an uncaught exception or a sanitizer report is a
// finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "facet/framework/diagnostics.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/registry.hpp"
#include "facet/framework/validated_graph.hpp"
#include "io/depth_sink.hpp"
#include "io/frames_source.hpp"
#include "io/labels_sink.hpp"
#include "io/overlay_sink.hpp"

namespace {

const facet::Registry& registry() {
  static const facet::Registry stages = [] {
    facet::Registry r;
    r.add<facet::io::FramesSource>();
    r.add<facet::io::DepthSink>();
    r.add<facet::io::LabelsSink>();
    r.add<facet::io::OverlaySink>();
    return r;
  }();
  return stages;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string yaml(reinterpret_cast<const char*>(data), size);
  facet::Diagnostics diagnostics;
  const facet::GraphSpec graph =
      facet::load_graph_text(yaml, "fuzz/graph.yaml", facet::LoadOptions{}, diagnostics);
  facet::Diagnostics validation;
  (void)facet::validate_graph(graph, registry(), validation);
  (void)diagnostics.str();
  (void)validation.str();
  // The first few variants as `--variant` selects them: their extends chains, replaced nodes and
  // sets are resolved only then.
  constexpr std::size_t kVariantsTried = 4;
  for (std::size_t v = 0; v < graph.variants.size() && v < kVariantsTried; ++v) {
    facet::LoadOptions options;
    options.variant = graph.variants[v];
    facet::Diagnostics variant_diagnostics;
    const facet::GraphSpec variant =
        facet::load_graph_text(yaml, "fuzz/graph.yaml", options, variant_diagnostics);
    (void)facet::validate_graph(variant, registry(), variant_diagnostics);
    (void)variant_diagnostics.str();
  }
  return 0;
}
