#pragma once
// Which surface patches touch: the graph that object segmentation (BSP, convex merging) works on.

#include <cstdint>
#include <utility>
#include <vector>

#include "facet/packet.hpp"
#include "facet/types/frame.hpp"

namespace facet {

// Patches are the ids 1..count of the LabelImage produced alongside. Each pair (a, b) with a < b
// appears once, sorted; `contact_px[i]` counts the pixel contacts that made pair i adjacent
// (a measure of how long the shared border is).
struct PatchAdjacency : FrameHeader {
  std::int32_t count = 0;
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  std::vector<std::int32_t> contact_px;
};

}  // namespace facet

FACET_TYPE_KEY(facet::PatchAdjacency, "facet.PatchAdjacency/1");
