#pragma once
// The 8 neighbours of a pixel in raster order, as (dx, dy). Where several neighbours tie, the
// assignment takes the first in this order.

namespace facet::grow {

inline constexpr int kNeighbourSteps[8][2] = {{-1, -1}, {0, -1}, {1, -1}, {-1, 0},
                                              {1, 0},   {-1, 1}, {0, 1},  {1, 1}};

}  // namespace facet::grow
