#pragma once
// Checks --sweep axes against the graph they will vary, before anything runs, so that a typo
// or a value out of range is one clear error about the option instead of one error per point.

#include <string>
#include <utility>
#include <vector>

#include "facet/framework/diagnostics.hpp"
#include "facet/framework/graph_spec.hpp"
#include "facet/framework/registry.hpp"
#include "facet/framework/sweep_spec.hpp"

namespace facet {

// Reports against `<command line>`: an axis named twice, a grid of more than kMaxSweepPoints, a
// parameter also given by --set (`sets`), an unknown node or parameter (with a suggestion), a
// parameter that is not an integer or a real, an integer parameter with a fractional start,
// stop or step, and every value outside the parameter's range or choices. `graph` is the graph
// as the sweep starts from it (its variant applied), so that a replaced stage's parameters count.
void check_sweep_axes(const std::vector<SweepAxis>& axes, const GraphSpec& graph,
                      const Registry& registry,
                      const std::vector<std::pair<std::string, std::string>>& sets,
                      Diagnostics& diagnostics);

}  // namespace facet
