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
using Bytes = std::int8_t __attribute__((vector_size(8)));

// Unaligned load. (Through a reference: a vector returned by value draws an ABI warning in the
// default clone.)
template <class Vector, class T>
void load(Vector& to, const T* from) {
  std::memcpy(&to, from, sizeof(to));
}

}  // namespace

__attribute__((target_clones("avx2", "default"))) int assign_nearest_neighbours(
    const NeighbourRows& rows, const std::uint8_t* candidate, std::uint8_t round, float gate_sq_m2,
    std::int32_t* label_row, std::uint8_t* state_row, std::int32_t* wide_state_row, int width) {
  const Ints round_lanes = Ints{} + round;
  const std::uint64_t round_bytes = 0x0101010101010101ULL * round;
  int assigned = 0;
  for (int x0 = 0; x0 < width; x0 += 8) {
    std::uint64_t word = 0;
    std::memcpy(&word, candidate + x0, sizeof(word));
    if (word == 0) continue;
    Bytes candidate_bytes;
    std::memcpy(&candidate_bytes, &word, sizeof(word));
    const Ints is_candidate = __builtin_convertvector(candidate_bytes, Ints);
    Floats px;
    Floats py;
    Floats pz;
    load(px, rows.coordinates[1][0] + x0);
    load(py, rows.coordinates[1][1] + x0);
    load(pz, rows.coordinates[1][2] + x0);
    Floats best_sq = Floats{} + gate_sq_m2;
    Ints found = Ints{};
    Ints best_label = Ints{};
    for (int n = 0; n < 8; ++n) {
      const int row = kNeighbourSteps[n][1] + 1;
      const int x = x0 + kNeighbourSteps[n][0];
      Floats qx;
      Floats qy;
      Floats qz;
      Ints state;
      Ints label;
      load(qx, rows.coordinates[row][0] + x);
      load(qy, rows.coordinates[row][1] + x);
      load(qz, rows.coordinates[row][2] + x);
      load(state, rows.state[row] + x);
      load(label, rows.labels[row] + x);
      const Floats ex = qx - px;
      const Floats ey = qy - py;
      const Floats ez = qz - pz;
      const Floats distance_sq = ex * ex + ey * ey + ez * ez;
      const Ints labelled = state < round_lanes;
      const Ints closer = labelled & (distance_sq < best_sq);  // false for NaN
      best_sq = closer ? distance_sq : best_sq;
      found |= closer;
      best_label = closer ? label : best_label;
    }
    const Ints take = found & (is_candidate != 0);
    const Bytes take_bytes = __builtin_convertvector(take, Bytes);  // 0 or -1 per lane
    std::uint64_t take_mask = 0;
    std::memcpy(&take_mask, &take_bytes, sizeof(take_mask));
    if (take_mask == 0) continue;
    assigned += __builtin_popcountll(take_mask) / 8;
    if (x0 + 8 <= width) {
      Ints labels;
      Ints wide_state;
      std::uint64_t state_bytes = 0;
      load(labels, label_row + x0);
      load(wide_state, wide_state_row + x0);
      std::memcpy(&state_bytes, state_row + x0, sizeof(state_bytes));
      labels = take ? best_label : labels;
      wide_state = take ? round_lanes : wide_state;
      state_bytes = (state_bytes & ~take_mask) | (round_bytes & take_mask);
      std::memcpy(label_row + x0, &labels, sizeof(labels));
      std::memcpy(wide_state_row + x0, &wide_state, sizeof(wide_state));
      std::memcpy(state_row + x0, &state_bytes, sizeof(state_bytes));
    } else {
      // The row's last, partial word: a whole-vector store would reach into the next row.
      for (int x = x0; x < width; ++x) {
        if (take[x - x0] == 0) continue;
        label_row[x] = best_label[x - x0];
        state_row[x] = round;
        wide_state_row[x] = round;
      }
    }
  }
  return assigned;
}

}  // namespace facet::grow
