#pragma once
// Checks --sweep axes against the graph they will vary, before anything runs, so that a typo
// or a value out of range is one clear error about the option instead of one error per point.

#include <vector>

#include "facet/framework/diagnostics.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/registry.hpp"
#include "facet/framework/sweep_spec.hpp"

namespace facet {

// Reports against `<command line>`: an axis named twice, a grid of more than kMaxSweepPoints, a
// parameter also given by --set or --param (`given`), an unknown node, parameter or graph
// parameter (with a suggestion), a parameter that is not an integer or a real, an integer
// parameter with a fractional start, stop or step, and every value outside the parameter's range
// or choices. A graph parameter is checked through the node parameters it sets (those written
// with its ${name}): it must set at least one, each numeric, and none also swept on its own.
// `graph` is the graph as the sweep starts from it (its variant applied), so that a replaced
// stage's parameters count.
void check_sweep_axes(const std::vector<SweepAxis>& axes, const GraphSpec& graph,
                      const Registry& registry, const LoadOptions& given, Diagnostics& diagnostics);

}  // namespace facet
