#include "grow/assignment_rows.hpp"

#include <cstring>

#include "grow/neighbour_steps.hpp"
#include "grow/pixel_classes.hpp"

namespace facet::grow {

__attribute__((target_clones("avx2", "default"))) int fill_state_row(
    const std::int32_t* __restrict labels, const std::uint8_t* __restrict classes,
    std::uint8_t* __restrict state, int width) {
  int unassigned_px = 0;
  for (int x = 0; x < width; ++x) {
    const std::uint8_t open = classes[x] != kInvalidPixel ? kUnassignedState : kInvalidState;
    const std::uint8_t value = labels[x] != 0 ? std::uint8_t{0} : open;
    state[x] = value;
    unassigned_px += value == kUnassignedState ? 1 : 0;
  }
  return unassigned_px;
}

__attribute__((target_clones("avx2", "default"))) void find_round_candidates(
    const std::uint8_t* __restrict up, const std::uint8_t* __restrict mid,
    const std::uint8_t* __restrict down, std::uint8_t newest, std::uint8_t* __restrict candidate,
    int width) {
  for (int x = 0; x < width; ++x) {
    const bool touches = (up[x - 1] == newest) | (up[x] == newest) | (up[x + 1] == newest) |
                         (mid[x - 1] == newest) | (mid[x + 1] == newest) | (down[x - 1] == newest) |
                         (down[x] == newest) | (down[x + 1] == newest);
    candidate[x] = static_cast<std::uint8_t>(touches & (mid[x] == kUnassignedState));
  }
}

namespace {

// Eight lanes, one per pixel of a word; GCC lowers them to one AVX2 register or two SSE ones.
using Floats = float __attribute__((vector_size(32)));
using Ints = std::int32_t __attribute__((vector_size(32)));

// Unaligned load. (Through a reference: a vector returned by value draws an ABI warning in the
// default clone.)
template <class Vector, class T>
void load(Vector& to, const T* from) {
  std::memcpy(&to, from, sizeof(to));
}

}  // namespace

__attribute__((target_clones("avx2", "default"))) void choose_nearest_neighbours(
    const NeighbourRows& rows, const std::uint8_t* __restrict candidate, std::uint8_t round,
    float gate_sq_m2, std::int32_t* __restrict choice, int width) {
  const Ints round_lanes = Ints{} + round;
  for (int x0 = 0; x0 < width; x0 += 8) {
    std::uint64_t word = 0;
    std::memcpy(&word, candidate + x0, sizeof(word));
    if (word == 0) continue;
    Floats px;
    Floats py;
    Floats pz;
    load(px, rows.coordinates[1][0] + x0);
    load(py, rows.coordinates[1][1] + x0);
    load(pz, rows.coordinates[1][2] + x0);
    Floats best_sq = Floats{} + gate_sq_m2;
    Ints best = Ints{};
    for (int n = 0; n < 8; ++n) {
      const int row = kNeighbourSteps[n][1] + 1;
      const int x = x0 + kNeighbourSteps[n][0];
      Floats qx;
      Floats qy;
      Floats qz;
      Ints state;
      load(qx, rows.coordinates[row][0] + x);
      load(qy, rows.coordinates[row][1] + x);
      load(qz, rows.coordinates[row][2] + x);
      load(state, rows.state[row] + x);
      const Floats ex = qx - px;
      const Floats ey = qy - py;
      const Floats ez = qz - pz;
      const Floats distance_sq = ex * ex + ey * ey + ez * ez;
      const Ints labelled = state < round_lanes;
      const Ints closer = labelled & (distance_sq < best_sq);  // false for NaN
      best_sq = closer ? distance_sq : best_sq;
      best = closer ? Ints{} + (n + 1) : best;
    }
    std::memcpy(choice + x0, &best, sizeof(best));
  }
}

}  // namespace facet::grow
